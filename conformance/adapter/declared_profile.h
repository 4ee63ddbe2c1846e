// declared_profile.h — what an implementation behind the exec route
// declares it does not show, read from its ?capabilities answer, as the
// limits of its route.
//
// Spec: docs/adapters.md section 1 ("A declared profile") and section 7
// ("What the wire route can and cannot judge"); issue 27, Deliver item 4
// (a declared profile on every route: the same code gets the same status
// for every clause on exec and on the Verse wire, or a stated route limit).
//
// Rationale: the Verse wire route knows what a Verse host cannot show (no
// derived document, no subscription column, no verdicts, no requests, and
// in r6's form no bone rotation: verse_route_limits). A program behind the
// exec route can be a wrapper around such a host (tests/verse/r6_interop's
// vgc_r6_exec) or a store that computes nothing derived; without a way to
// say so, vgc judged documents the program made up (the reference's
// derivation of the host's state) and passed or failed clauses the wire
// route calls not judgeable. The program declares it with words of its
// ?capabilities answer, "profile:WORD", which a vgc that predates them
// ignores (words that name no capability are ignored), and each word
// becomes the route limit it names, with the program's declaration as the
// why. The clauses a limit hides are route_limit_clauses.h's, as on the
// wire. A word this vgc does not know is named in the route's text (the
// report's header) and limits nothing; it is never an error.
//
//   profile:no-derived            it computes no derived document: ?derived is never asked, and
//                                 the clauses only that document decides are not-applicable
//   profile:subscriptions-unseen  its snapshot's subscription column is not its own (compared as
//                                 "-" on both sides; LAYER-SUBSCRIBE-1 not-applicable)
//   profile:no-verdicts           it reports no verdicts (answers `done`): REASON-1 not-applicable
//   profile:no-bone-rotation      its bone_create carries no rotation (r6's form): a bone_create
//                                 with another rotation than the identity is not sent and its
//                                 step not judged (as on the wire); BONE-VALUE-1 not-applicable
//   profile:no-requests           it answers no capability request: the capability clauses are
//                                 not-applicable rather than not-claimed
//   profile:c-string-names        its names are C strings: a command whose name holds a NUL byte
//                                 is not sent and its step is not judged (as on the Verse wire)
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "command.h"
#include "implementation.h"

namespace vgc {

// At most this many profile words are read from one answer, each cut to
// kMaxProfileWordBytes: an implementation's answer bounds nothing of ours.
inline constexpr std::size_t kMaxProfileWords = 16;
inline constexpr std::size_t kMaxProfileWordBytes = 40;

struct DeclaredProfile {
  // The "profile:WORD" words of the answer's first line, in order, without
  // the prefix (bounded as above; unprintable bytes escaped).
  std::vector<std::string> words;
  // The words vgc does not know, in order.
  std::vector<std::string> unknown;
  // The limits the known words declare; an empty route (no limits) when
  // there are no words at all.
  RouteLimits limits;
  // profile:c-string-names: a name with a NUL byte inside cannot reach it.
  bool c_string_names = false;
  // profile:no-bone-rotation: a rotation other than the identity cannot.
  bool no_bone_rotation = false;
};

// The profile declared by a ?capabilities answer (the whole document, or
// its first line). An answer that is not a capabilities document declares
// nothing.
DeclaredProfile declared_profile(const std::string& capabilities_answer);

// Whether `c` carries a name with a NUL byte inside (layer, bone, crease
// and label names): what an implementation whose names are C strings
// cannot receive.
bool has_name_with_nul(const Command& c);

// Whether `c` is a bone_create (not its destroy alias, an empty weight)
// whose rotation is not the identity 0 0 0 1, bit for bit (-0 is not):
// what a bone_create without a rotation (r6's form) cannot carry, as the
// wire encoder says (verse/wire_commands.cpp).
bool has_bone_rotation(const Command& c);

}  // namespace vgc
