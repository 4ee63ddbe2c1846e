// live_implementation.cpp — see live_implementation.h.
#include "live_implementation.h"

#include <charconv>
#include <cstdlib>
#include <fstream>

#include "capability.h"
#include "launched_host.h"
#include "restartable_host.h"

namespace vgc::fuzz {
namespace {

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

OpenOptions open_options(const LiveOptions& o) {
  OpenOptions options;
  options.timeout_seconds = o.timeout_s;
  if (!o.verse_bone_form.empty()) options.verse_bone_form = o.verse_bone_form;
  return options;
}

}  // namespace

LiveOptions live_options_from_environment() {
  LiveOptions o;
  o.spec = env_or("VGC_FUZZ_IMPL", "");
  const std::string t = env_or("VGC_FUZZ_TIMEOUT", "");
  if (!t.empty()) {
    double v = 0;  // the campaign writes it (--timeout, already checked); anything else keeps the default
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec == std::errc() && end == t.data() + t.size() && v > 0) o.timeout_s = v;
  }
  o.verse_bone_form = env_or("VGC_FUZZ_VERSE_BONE_FORM", "");
  o.restart = env_or("VGC_FUZZ_RESTART", "");
  o.host_cmd = env_or("VGC_FUZZ_HOST_CMD", "");
  o.host_log = env_or("VGC_FUZZ_HOST_LOG", "");
  if (!o.spec.empty()) o.route = parse_route(o.spec, &o.route_error);
  // The baseline's clause ids: the first word of every line that is not a
  // comment (conformance/report/baseline.h; the campaign parsed it whole).
  if (const std::string path = env_or("VGC_FUZZ_BASELINE", ""); !path.empty()) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      const auto start = line.find_first_not_of(" \t");
      if (start == std::string::npos || line[start] == '#') continue;
      o.tolerated.insert(line.substr(start, line.find_first_of(" \t", start) - start));
    }
  }
  return o;
}

bool can_confirm_on_fresh_instance(const LiveOptions& o) {
  return (o.route && o.route->traits().restartable) || !o.restart.empty() || !o.host_cmd.empty();
}

std::unique_ptr<Implementation> open_live_implementation(const LiveOptions& o, std::string* error) {
  if (!o.route) {
    *error = o.route_error;
    return nullptr;
  }
  if (o.route->traits().in_process) {
    *error = "'" + o.spec + "': a live implementation is exec:CMD or verse:[NAME@]HOST[:PORT]";
    return nullptr;
  }
  if (!o.host_cmd.empty() && o.route->kind != RouteKind::Verse) {
    *error = "VGC_FUZZ_HOST_CMD (--host-cmd) is for a verse: host, not '" + o.spec + "'";
    return nullptr;
  }
  std::unique_ptr<Implementation> sut =
      o.host_cmd.empty() ? open_restartable(*o.route, open_options(o), o.restart, error)
                         : open_launched_host(*o.route, open_options(o), o.host_cmd, o.host_log, error);
  // An exec program declares what it does not show in its ?capabilities
  // answer (declared_profile.h): asked once here, so every input is judged
  // by that profile from the first, as certify judges.
  if (sut) (void)query_capabilities(*sut);
  return sut;
}

}  // namespace vgc::fuzz
