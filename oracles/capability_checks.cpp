// capability_checks.cpp — registers the five capability checks
// (capability_checks.h) with the runner; each check is a file of its own:
// check_classify.cpp, check_subdivision.cpp, check_normals.cpp,
// check_loop.cpp, check_edits.cpp.
#include "capability_checks.h"

#include <cstdint>
#include <utility>

namespace vgc {

void register_capability_checks() {
  auto add = [](const char* name, decltype(CapabilityCheck::check) check) {
    CapabilityCheck c;
    c.capability = name;
    c.check = std::move(check);
    register_capability_check(std::move(c));
  };
  add("manifold", [](const Node& m, Implementation& s, int) { return check_classify(m, s); });
  add("subdivision", [](const Node& m, Implementation& s, int level) { return check_subdivision(m, s, level); });
  add("normals", [](const Node& m, Implementation& s, int) { return check_normals(m, s); });
  add("loop", [](const Node& m, Implementation& s, int level) { return check_loop(m, s, level); });
  CapabilityCheck edits;
  edits.capability = "edits";
  edits.check_drawn = [](const Node& m, Implementation& s, int level, std::uint32_t draw) {
    return check_edits(m, s, level, draw);
  };
  register_capability_check(std::move(edits));
}

}  // namespace vgc
