// costly_class.h — a class of input that costs the implementation a
// time-out: found once, then no longer drawn for the rest of the run.
//
// Spec: ID-BOUND-1 and the element id fields of the geometry commands
// (docs/spec_facts.md "Command set of the geometry node"; ids are 32 bits
// for vertices and polygons); docs/certify.md "A costly class is found once".
//
// Rationale: an implementation whose storage is dense (an array indexed by
// id) makes millions of slots for one sparse id the generators draw (2^22,
// 2^23, ...): its every call after that takes longer than the call limit.
// One such time-out is a finding, on the clause of the command that drew
// the id, with its counterexample. But every later case that draws an id of
// that magnitude costs another time-out and a restart, so a run spent its
// whole budget on the one class and left a third of the catalog unchecked.
// So the first time-out on a command names a class: "vertex ids of 2^22 or
// more" (the kind of element the command's largest element id names, from
// the power of two at or below it). The runner then sends no command of an
// avoided class for the rest of the run (property_case.cpp, Step::run): the
// classes avoided are listed in the run's report, so a reader knows what
// was not drawn again and why.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "command.h"

namespace vgc {

enum class ElementKind { Vertex, Polygon };

struct CostlyClass {
  ElementKind kind = ElementKind::Vertex;
  std::uint32_t floor = 0;  // a power of two: ids of `kind` at or above it
};

// The class of `c`'s largest element id (a vertex or polygon id, a
// polygon's corner is a vertex id; the "pick one" and "unused corner"
// sentinel 0xFFFFFFFF is no id), from the power of two at or below it;
// nullopt when it has no element id or that id is below 2^8 (a class that
// small is every mesh: nothing would be left to draw).
std::optional<CostlyClass> costly_class_of(const Command& c);

// Whether `c` names an element id in one of the `avoided` classes.
bool in_costly_class(const Command& c, const std::vector<CostlyClass>& avoided);

// "vertex ids of 2^22 (4194304) or more".
std::string describe_costly_class(const CostlyClass& k);

}  // namespace vgc
