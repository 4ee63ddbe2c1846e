// route.h — an `--impl` value as a value: which route it takes to the
// implementation under test, what it names there, and what that route can
// and cannot do; and the one table of the routes vgc knows.
//
// Spec: docs/adapters.md (the routes: exec:CMD section 1, plugin:PATH
// section 4, verse:[NAME@]HOST[:PORT] section 7; "reference" is vgc's own
// node), docs/certify.md (--impl), docs/fuzzing.md (a live implementation).
//
// Rationale (issue 29, "a route is a value"): a decision that depends on
// the route (may --verse-bone-form be given, can a finding be confirmed on a
// fresh instance, does libFuzzer load the implementation into its own
// process or drive it through an adapter) asks the route's traits, never
// the text of the spec again. The text is read here once, by parse_route,
// into a Route; every route's prefix, traits and opener stand in one row of
// route_registry(). A new route is a new row: no other file tests a prefix.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vgc {

class Implementation;
struct OpenOptions;

enum class RouteKind {
  Reference,  // "reference": vgc's own node, in process
  Exec,       // "exec:CMD": a program speaking the exec protocol on stdin/stdout
  Plugin,     // "plugin:PATH": a shared library with the C ABI of vgc_plugin.h
  Verse,      // "verse:[NAME@]HOST[:PORT]": a running Verse host, over its own wire
};

// What a route can do, whatever implementation is at its end.
struct RouteTraits {
  // The implementation can run inside a vgc process: the reference, and a
  // plugin (which certify isolates in a child process unless told not to,
  // OpenOptions::isolate_plugin, and which a libFuzzer target loads into
  // its own). The others are running programs reached through an adapter
  // ("live" implementations for `vgc fuzz differential`).
  bool in_process = false;
  // vgc can start a fresh instance of it by itself (a new process, a new
  // node with nothing behind it): how a finding is confirmed
  // (confirm_finding.h). A host on the Verse wire is a server vgc did not
  // start: only a restart command the user gives can give a fresh one
  // (restartable_host.h).
  bool restartable = false;
  // The route carries the derived document (effective creases, bone world
  // poses) besides the stored state.
  bool derived_documents = false;
  // The route carries a verdict per command (applied, or rejected with a
  // reason); an exec program may still answer `done`, saying none.
  bool reports_verdicts = false;
  // The route carries the optional capability requests (?classify,
  // ?subdivide, ...: docs/adapters.md section 5).
  bool answers_requests = false;
  // The implementation declares, at the route's start, a profile vgc
  // follows: today only the bone_create form a Verse host speaks
  // (--verse-bone-form, docs/verse_wire.md section 4). The exec and plugin
  // routes declare their capabilities (?capabilities), which every route
  // that answers requests asks, and an exec program its profile there too
  // (declared_profile.h: what it cannot show, as route limits); no route
  // declares the IMPLEMENTATION-DEFINED readings it follows yet.
  bool declares_bone_form = false;
};

// An --impl value, read once.
struct Route {
  RouteKind kind = RouteKind::Reference;
  std::string spec = "reference";  // the text as given: the implementation's name in reports and replay lines
  std::string target;              // after the prefix: exec: the command, plugin: the path, verse: the address
  // verse: the address, read (parse_verse_address): login name, host, port.
  std::string login, host;
  std::uint16_t port = 0;

  const RouteTraits& traits() const;
  // The route's form for messages: "exec:CMD", "verse:[NAME@]HOST[:PORT]".
  const char* form() const;
};

// One row of the table: the route's kind, its prefix ("exec:"; the whole
// word for "reference"), its form for messages, its traits, and how an
// implementation is opened on it (started, logged in to; nullptr with
// *error when it cannot be).
struct RouteEntry {
  RouteKind kind;
  const char* prefix;
  const char* form;
  const char* what;  // what the form names, for the list of forms in a message
  RouteTraits traits;
  std::unique_ptr<Implementation> (*open)(const Route& route, const OpenOptions& options, std::string* error);
};

// Every route vgc knows, one row each.
const std::vector<RouteEntry>& route_registry();

// `spec` as a Route, or nullopt with *error: an unknown form, a form that
// names nothing ("exec:", "plugin:"), a Verse address that does not parse.
// The message lists the forms vgc takes (route_forms()).
std::optional<Route> parse_route(const std::string& spec, std::string* error);

// "expected reference, exec:CMD (...), plugin:PATH (...) or verse:... (...)".
std::string route_forms();

// The spec of the route of `kind` to `target` ("plugin:" + path).
std::string route_spec(RouteKind kind, const std::string& target);

// Opens the implementation at the end of `route`.
std::unique_ptr<Implementation> open_route(const Route& route, const OpenOptions& options, std::string* error);

}  // namespace vgc
