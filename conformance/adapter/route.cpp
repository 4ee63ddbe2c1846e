// route.cpp — see route.h. The table of routes: "reference", "exec:CMD",
// "plugin:PATH", "verse:[NAME@]HOST[:PORT]", each with its traits and its
// opener.
//
// Spec: docs/adapters.md. An isolated plugin is `<vgc> serve --impl
// plugin:PATH` behind the exec adapter, so a plugin that crashes or hangs
// is a Crash or Timeout result like any exec program's.
#include "route.h"

#include <unistd.h>

#include <climits>

#include "exec_implementation.h"
#include "implementation.h"
#include "plugin_implementation.h"
#include "reference_implementation.h"
#include "verse_implementation.h"

namespace vgc {
namespace {

std::string self_executable() {
  char buf[PATH_MAX + 1];
  const ssize_t n = readlink("/proc/self/exe", buf, PATH_MAX);
  if (n <= 0) return {};
  return std::string(buf, static_cast<std::size_t>(n));
}

std::unique_ptr<Implementation> start_exec(const std::string& command, const std::string& display_name,
                                           const OpenOptions& options, std::string* error) {
  auto impl = std::make_unique<ExecImplementation>(command, options, display_name);
  const Answer a = impl->start();
  if (a.status != CallStatus::Ok) {
    *error = impl->name() + ": cannot start it (" + call_status_name(a.status) + "): " + a.detail;
    return nullptr;
  }
  return impl;
}

std::unique_ptr<Implementation> open_reference(const Route&, const OpenOptions&, std::string*) {
  return std::make_unique<ReferenceImplementation>();
}

std::unique_ptr<Implementation> open_exec(const Route& r, const OpenOptions& options, std::string* error) {
  return start_exec(r.target, r.spec, options, error);
}

std::unique_ptr<Implementation> open_plugin(const Route& r, const OpenOptions& options, std::string* error) {
  if (!options.isolate_plugin) return PluginImplementation::load(r.target, error);
  const std::string vgc = options.vgc_binary.empty() ? self_executable() : options.vgc_binary;
  if (vgc.empty()) {
    *error = r.spec + ": cannot find the vgc program to isolate the plugin in (set OpenOptions::vgc_binary)";
    return nullptr;
  }
  return start_exec(shell_quote(vgc) + " serve --impl " + shell_quote(r.spec), r.spec, options, error);
}

std::unique_ptr<Implementation> open_verse(const Route& r, const OpenOptions& options, std::string* error) {
  auto impl = std::make_unique<VerseImplementation>(r.spec, r.login, r.host, r.port, options);
  const Answer a = impl->start();
  if (a.status != CallStatus::Ok) {
    *error = r.spec + ": cannot certify this host (" + call_status_name(a.status) + "): " + a.detail +
             ". Is a Verse host listening there (UDP), and does it accept the login? (docs/adapters.md, "
             "\"The Verse wire route\")";
    return nullptr;
  }
  return impl;
}

// What the target of a route names, for "'exec:' names no command".
const char* target_noun(RouteKind k) { return k == RouteKind::Exec ? "command" : "library"; }

}  // namespace

const std::vector<RouteEntry>& route_registry() {
  //                       in_process restartable derived verdicts requests bone_form
  static const std::vector<RouteEntry> routes = {
      {RouteKind::Reference, "reference", "reference", "vgc's own node", {true, true, true, true, true, false},
       open_reference},
      {RouteKind::Exec, "exec:", "exec:CMD", "a program speaking the exec protocol, run with /bin/sh -c",
       {false, true, true, true, true, false}, open_exec},
      {RouteKind::Plugin, "plugin:", "plugin:PATH", "a shared library exporting vgc_plugin_v1",
       {true, true, true, true, true, false}, open_plugin},
      {RouteKind::Verse, "verse:", "verse:[NAME@]HOST[:PORT]", "a Verse host, port 4950 by default",
       {false, false, false, false, false, true}, open_verse},
  };
  return routes;
}

namespace {

const RouteEntry& entry_of(RouteKind k) {
  for (const RouteEntry& e : route_registry())
    if (e.kind == k) return e;
  return route_registry().front();  // unreachable: every kind has its row
}

}  // namespace

const RouteTraits& Route::traits() const { return entry_of(kind).traits; }
const char* Route::form() const { return entry_of(kind).form; }

std::string route_forms() {
  // "expected reference, exec:CMD (...), plugin:PATH (...) or verse:... (...)"
  const auto& routes = route_registry();
  std::string out = "expected ";
  for (std::size_t i = 0; i < routes.size(); ++i) {
    const RouteEntry& e = routes[i];
    out += i == 0 ? "" : i + 1 == routes.size() ? " or " : ", ";
    out += e.form;
    if (e.kind != RouteKind::Reference) out += std::string(" (") + e.what + ")";
  }
  return out;
}

std::string route_spec(RouteKind kind, const std::string& target) {
  const RouteEntry& e = entry_of(kind);
  return kind == RouteKind::Reference ? std::string(e.prefix) : e.prefix + target;
}

std::optional<Route> parse_route(const std::string& spec, std::string* error) {
  for (const RouteEntry& e : route_registry()) {
    Route r;
    r.kind = e.kind;
    r.spec = spec;
    if (e.kind == RouteKind::Reference) {
      if (spec == e.prefix) return r;
      continue;
    }
    const std::string prefix = e.prefix;
    if (spec.compare(0, prefix.size(), prefix) != 0) continue;
    r.target = spec.substr(prefix.size());
    switch (e.kind) {
      case RouteKind::Reference: break;
      case RouteKind::Exec:
      case RouteKind::Plugin:
        if (r.target.find_first_not_of(e.kind == RouteKind::Exec ? " \t" : "") == std::string::npos) {
          *error = "'" + spec + "' names no " + target_noun(e.kind) + "; " + route_forms();
          return std::nullopt;
        }
        break;
      case RouteKind::Verse: {
        std::string why;
        if (!parse_verse_address(r.target, &r.login, &r.host, &r.port, &why)) {
          *error = "'" + spec + "': " + why + "; " + route_forms();
          return std::nullopt;
        }
        break;
      }
    }
    return r;
  }
  *error = "unknown implementation '" + spec + "': " + route_forms();
  return std::nullopt;
}

std::unique_ptr<Implementation> open_route(const Route& route, const OpenOptions& options, std::string* error) {
  return entry_of(route.kind).open(route, options, error);
}

std::unique_ptr<Implementation> open_implementation(const std::string& spec, const OpenOptions& options,
                                                    std::string* error) {
  const std::optional<Route> route = parse_route(spec, error);
  if (!route) return nullptr;
  return open_route(*route, options, error);
}

}  // namespace vgc
