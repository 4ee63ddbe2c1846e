// declared_profile.cpp — see declared_profile.h.
#include "declared_profile.h"

#include <array>
#include <cstring>
#include <sstream>
#include <type_traits>
#include <variant>

#include "display_text.h"

namespace vgc {
namespace {

std::string joined(const std::vector<std::string>& words, const char* prefix) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + (prefix + w);
  return out;
}

}  // namespace

DeclaredProfile declared_profile(const std::string& capabilities_answer) {
  DeclaredProfile p;
  const std::string first = capabilities_answer.substr(0, capabilities_answer.find('\n'));
  std::istringstream words(first);
  std::string w;
  if (!(words >> w) || w != "capabilities") return p;
  while (words >> w && p.words.size() < kMaxProfileWords) {
    if (w.rfind("profile:", 0) != 0 || w.size() == 8) continue;
    p.words.push_back(escape_unprintable(w.substr(8, kMaxProfileWordBytes)));
  }
  if (p.words.empty()) return p;
  RouteLimits& l = p.limits;
  for (const std::string& word : p.words) {
    const std::string by = "it declares so (profile:" + word + " in its ?capabilities answer)";
    if (word == "no-derived") {
      l.derived = false;
      l.why_no_derived = "the implementation computes no derived document: " + by;
    } else if (word == "subscriptions-unseen") {
      l.subscriptions = false;
      l.cannot[RouteLimit::SubscriptionsUnseen] =
          "its snapshot's subscription column is not its own, so it is compared as \"-\": " + by;
    } else if (word == "no-verdicts") {
      l.cannot[RouteLimit::NoVerdicts] = "it reports no verdicts, so it gives no reason codes: " + by;
    } else if (word == "no-bone-rotation") {
      p.no_bone_rotation = true;
      l.cannot[RouteLimit::BoneRotationUnsent] =
          "its bone_create carries no rotation (r6's form), so a non-finite or zero rotation cannot reach it: " + by;
    } else if (word == "no-requests") {
      l.cannot[RouteLimit::NoRequests] =
          "an optional capability is asked with a request (docs/adapters.md section 5), and it answers none: " + by;
    } else if (word == "c-string-names") {
      p.c_string_names = true;
    } else {
      p.unknown.push_back(word);
    }
  }
  l.route = "the exec route with the profile the implementation declares (" + joined(p.words, "profile:") + ")";
  if (!p.unknown.empty())
    l.route += "; not known to this vgc, so limiting nothing: " + joined(p.unknown, "profile:");
  return p;
}

bool has_name_with_nul(const Command& c) {
  const auto nul = [](const std::string& s) { return s.find('\0') != std::string::npos; };
  return std::visit(
      [&](const auto& x) -> bool {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, cmd::LayerCreate>) return nul(x.name);
        else if constexpr (std::is_same_v<T, cmd::CreaseSetVertex> || std::is_same_v<T, cmd::CreaseSetEdge>)
          return nul(x.layer);
        else if constexpr (std::is_same_v<T, cmd::BoneCreate>)
          return nul(x.weight) || nul(x.reference) || nul(x.pos_label) || nul(x.rot_label);
        else return false;
      },
      c);
}

bool has_bone_rotation(const Command& c) {
  static const std::array<double, 4> kIdentity{0, 0, 0, 1};
  const auto* b = std::get_if<cmd::BoneCreate>(&c);
  return b && !b->weight.empty() && std::memcmp(b->rot.data(), kIdentity.data(), sizeof kIdentity) != 0;
}

}  // namespace vgc
