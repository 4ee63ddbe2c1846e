// open_impl.cpp — see open_impl.h.
#include "open_impl.h"

#include <fmt/core.h>

#include <filesystem>

#include "option_values.h"
#include "launched_host.h"
#include "restartable_host.h"
#include "terminal_text.h"

#if __has_include("capability_checks.h")
#include "capability_checks.h"
#define VGC_HAVE_CAPABILITY_CHECKS 1
#endif

namespace vgc::cli {

namespace {

// What to do when `route` could not be opened with `error`: a line for the
// newcomer, after the adapter's own account of what happened.
std::string what_to_do(const Route& route, const std::string& error) {
  switch (route.kind) {
    case RouteKind::Exec:
      if (error.find("status 127") != std::string::npos)
        return "the shell found no such program: check the command; a relative path is relative to the directory "
               "vgc runs in";
      if (error.find("status 126") != std::string::npos)
        return "the program is not executable: chmod +x it, or name its interpreter (exec:'python3 my_host.py')";
      if (error.find("names no command") != std::string::npos) return "";
      return "check that the program speaks the exec protocol (docs/adapters.md section 1): printf "
             "'?hello\\n?quit\\n' | " + route.target + " must answer `vgc-exec 1 NAME`";
    case RouteKind::Plugin:
      if (error.find("names no library") != std::string::npos) return "";
      return "the plugin must be a shared library exporting the C function vgc_plugin_v1 (docs/adapters.md section "
             "4); `nm -D PATH | grep vgc_plugin_v1` shows whether it does";
    case RouteKind::Reference:
    case RouteKind::Verse: return "";
  }
  return "";
}

}  // namespace

void add_impl_options(CLI::App* sub, ImplOptions* o, unsigned which, const std::string& impl_help) {
  // The value is read into the route here, once; the option's own string
  // is not kept.
  const CLI::Validator route_value(
      [o](std::string& s) -> std::string {
        if (s.empty()) return "";  // said by the check every option has (option_values.h refuse_empty_values)
        std::string error;
        std::optional<Route> r = parse_route(s, &error);
        if (!r) return error;
        o->route = std::move(*r);
        o->impl_given = true;
        return "";
      },
      "ROUTE");
  sub->add_option_function<std::string>("--impl", [](const std::string&) {}, impl_help)
      ->check(route_value)
      ->default_str(o->route.spec);
  if (which & kTimeout)
    sub->add_option_function<double>(
           "--timeout", [o](double v) { o->timeout = v, o->timeout_given = true; },
           "Seconds an out-of-process implementation (exec:, an isolated plugin:, verse:) has per answer; longer "
           "is a hang (timeout)")
        ->default_str(fmt::format("{:g}", o->timeout))
        ->transform(seconds("per answer"));
  if (which & kStartTimeout)
    sub->add_option("--start-timeout", o->start_timeout,
                    "Seconds an out-of-process implementation has to start (exec: and plugin: the ?hello answer, "
                    "verse: the login), each time it is started")
        ->capture_default_str()
        ->transform(seconds("to start"));
  if (which & kBoneForm)
    sub->add_option_function<std::string>(
           "--verse-bone-form", [o](const std::string& v) { o->verse_bone_form = v, o->bone_form_given = true; },
           "verse: the bone_create form to speak: auto (the form the host answers a probe in), spec (Verse spec "
           "2.6.3) or r6 (r6's last release; docs/verse_wire.md section 4)")
        ->check(CLI::IsMember({"auto", "spec", "r6"}))
        ->default_str(o->verse_bone_form);
  if (which & kRestart)
    sub->add_option("--restart", o->restart,
                    "verse: a shell command that starts a fresh host (and returns once it listens); run before a "
                    "finding is confirmed on a fresh instance. Without it certify confirms a finding on a fresh node of "
                    "the same host process, and fuzz reports a crash or hang of the host unconfirmed");
  if (which & kHostCmd)
    sub->add_option("--host-cmd", o->host_cmd,
                    "verse: a shell command that runs the host in the foreground (e.g. './verse -port=4950'): vgc "
                    "starts it under its reaper, waits until it accepts a login, starts it again for a fresh "
                    "instance (instead of --restart), gives it the shared memory of its coverage (fuzz) and ends "
                    "it when vgc ends");
}

std::string impl_options_misuse(const ImplOptions& o) {
  if (o.bone_form_given && !o.route.traits().declares_bone_form)
    return "--verse-bone-form is for --impl verse:HOST[:PORT] only; --impl is '" + o.route.spec + "'";
  if (!o.restart.empty() && o.route.traits().restartable)
    return "--restart is for --impl verse:HOST[:PORT] only (vgc starts a fresh instance of '" + o.route.spec +
           "' itself)";
  if (!o.host_cmd.empty() && o.route.kind != RouteKind::Verse)
    return "--host-cmd is for --impl verse:HOST:PORT only (the host vgc starts and logs in to); --impl is '" +
           o.route.spec + "'";
  if (!o.host_cmd.empty() && !o.restart.empty())
    return "--host-cmd replaces --restart: vgc starts the host again itself for a fresh instance; give one of them";
  return "";
}

OpenOptions open_options_of(const ImplOptions& o) {
  OpenOptions open;
  open.timeout_seconds = o.timeout;
  open.start_timeout_seconds = o.start_timeout;
  open.verse_bone_form = o.verse_bone_form;
  return open;
}

std::unique_ptr<Implementation> open_impl_or_report(const char* subcommand, const ImplOptions& o) {
  const Route& route = o.route;
  // A plugin file that is not there: said plainly, not as a child process
  // that failed to answer.
  if (route.kind == RouteKind::Plugin) {
    const std::filesystem::path path = route.target;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      say(stderr,
          "vgc {}: {}: {} is {}: give the path of your plugin's shared library (relative to the directory vgc "
          "runs in, {}), e.g. plugin:./build/libmy_node.so\n",
          subcommand, route.spec, path.string(),
          std::filesystem::exists(path, ec) ? "not a regular file" : "not there",
          std::filesystem::current_path(ec).string());
      return nullptr;
    }
  }
  std::string error;
  auto sut = o.host_cmd.empty() ? open_restartable(route, open_options_of(o), o.restart, &error)
                                : open_launched_host(route, open_options_of(o), o.host_cmd, "", &error);
  if (!sut) {
    say(stderr, "vgc {}: {}\n", subcommand, error);
    if (const std::string fix = what_to_do(route, error); !fix.empty())
      say(stderr, "vgc {}: what to do: {}\n", subcommand, fix);
  }
  return sut;
}

bool register_oracle_checks() {
#ifdef VGC_HAVE_CAPABILITY_CHECKS
  register_capability_checks();  // the oracles judge the optional capabilities
  return true;
#else
  return false;
#endif
}

}  // namespace vgc::cli
