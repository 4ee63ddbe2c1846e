// capability.cpp — see capability.h.
#include "capability.h"

#include <map>
#include <sstream>

namespace vgc {
namespace {

std::map<std::string, CapabilityCheck>& registry() {
  static std::map<std::string, CapabilityCheck> r;
  return r;
}

}  // namespace

void register_capability_check(CapabilityCheck check) {
  const std::string name = check.capability;
  registry()[name] = std::move(check);
}

const CapabilityCheck* find_capability_check(const std::string& capability) {
  auto it = registry().find(capability);
  return it == registry().end() ? nullptr : &it->second;
}

std::vector<std::string> query_capabilities(Implementation& sut) {
  std::vector<std::string> out;
  const Document d = sut.request("?capabilities");
  if (d.status != CallStatus::Ok) return out;
  std::istringstream in(d.text);
  std::string first;
  if (!std::getline(in, first)) return out;
  std::istringstream words(first);
  std::string w;
  if (!(words >> w) || w != "capabilities") return out;
  while (words >> w) out.push_back(w);
  return out;
}

}  // namespace vgc
