// cmd_serve.cpp — `vgc serve [--impl reference|plugin:PATH] [--done]`: serve a node
// over the exec protocol (docs/adapters.md) on standard input and output;
// `vgc serve --verse [ADDR:]PORT [--impl ...]`: serve geometry nodes as a
// Verse r6 host over UDP (docs/verse_wire.md), one node of the --impl kind
// per node_create. It prints "vgc-verse listening ADDR:PORT" on stdout
// once bound (PORT 0 picks a free port and prints it), logs to stderr, and
// serves until SIGINT or SIGTERM (exit 0); 2 when it cannot bind or open
// the implementation.
//
// Spec: docs/adapters.md "The exec protocol"; command lines are the text
// language of docs/commands.md, documents those of snapshot.h and
// derived_document.h.
//
// Rationale: this is how the reference is certified through the exec route
// (`--impl exec:'vgc serve'`) and how a plugin runs isolated in a child
// process (open_implementation with isolate_plugin). One line in, one line
// out, flushed: a command answers "ok", "rejected <REASON>" or "error line
// 1, column N: ..." (the TextError of a line that does not parse), and the
// requests ?hello ?reset ?snapshot ?derived ?quit, ?digest (when the served
// implementation offers it: document_digest.h) and the optional
// capability requests (?capabilities ?classify ?subdivide ?normals ...,
// capability_document_header) are answered as the
// protocol says. A plugin's VGC_DONE is relayed as "done"; with --done every
// command is answered "done" instead of "ok" / "rejected <REASON>", the way
// a host on the Verse wire answers nothing (README: "Hosts on the wire send
// no acknowledgement and no error"), so the suite's `done` judging can be
// certified against the reference itself. Exit codes: 0 at ?quit or end of input; 2 when the
// implementation cannot be opened; 3 when writing the answer fails.
#include <fmt/core.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "capability_documents.h"
#include "command_text.h"
#include "implementation.h"
#include "open_impl.h"
#include "route.h"
#include "subcommand.h"
#include "verse_host.h"

namespace vgc::cli {
namespace {

struct ServeOptions {
  ImplOptions impl;  // --impl (open_impl.h); a plugin is loaded in this process
  bool done = false;  // answer every command "done" (verdict not reported)
  std::string verse;  // [ADDR:]PORT: serve as a Verse host instead
  bool like_r6 = false;  // --like-r6: reuse node ids, read and send bone_create in r6's form, strictly
  std::vector<std::string> r6_deviations;  // --r6-deviation NAME...
};

// The implementation behind one served Verse node: every answer is
// dropped (the wire has none); the host reads the snapshot, or the digest
// that confirms its own prediction, to see changes.
class ImplementationNode : public verse::HostedNode {
 public:
  explicit ImplementationNode(std::unique_ptr<Implementation> impl) : impl_(std::move(impl)) {}
  bool apply(const Command& command, std::string* error) override {
    const Answer a = impl_->apply(command);
    if (a.status == CallStatus::Ok) return true;
    *error = std::string(call_status_name(a.status)) + ": " + a.detail;
    return false;
  }
  bool snapshot(std::string* text, std::string* error) override {
    Document d = impl_->snapshot();
    if (d.status != CallStatus::Ok) {
      *error = std::string(call_status_name(d.status)) + ": " + d.detail;
      return false;
    }
    *text = std::move(d.text);
    return true;
  }
  // ?digest when the implementation offers it (an exec program claiming
  // `digest`, the reference): the host then follows the node at the cost of
  // each command (followed_node.h).
  bool offers_digest() override { return impl_->offers_digest(); }
  bool snapshot_digest(std::uint64_t* digest, std::string* error) override {
    const DigestAnswer d = impl_->digest();
    if (d.status != CallStatus::Ok) {
      *error = std::string(call_status_name(d.status)) + ": " + d.detail;
      return false;
    }
    *digest = d.digests.snapshot;
    return true;
  }

 private:
  std::unique_ptr<Implementation> impl_;
};

std::atomic<bool> g_stop{false};
extern "C" void on_stop_signal(int) { g_stop = true; }

int run_verse(const ServeOptions& o) {
  verse::HostOptions h;
  if (o.like_r6) {
    h.reuse_node_ids = true;
    h.bone_form = verse::BoneForm::R6;
    h.strict_bone_form = true;
  }
  for (const std::string& d : o.r6_deviations) {
    if (d == "announce-missing-deletes") h.announce_missing_deletes = true;
    else if (d == "xyz-no-default") h.xyz_no_default = true;
    else if (d == "both-formats") h.both_formats = true;
  }
  std::string error;
  if (!verse::parse_listen_address(o.verse, &h.address, &h.port, &error)) {
    fmt::print(stderr, "vgc serve --verse: {}\n", error);
    return 2;
  }
  OpenOptions options;
  options.isolate_plugin = false;
  // Opened now to fail now, not at the first node_create; and kept open:
  // a plugin stays loaded, so every node shares one copy of its code (a
  // plugin closed and loaded again lands elsewhere, and the coverage
  // runtime of an instrumented one would map its counters twice).
  const std::unique_ptr<Implementation> first = open_route(o.impl.route, options, &error);
  if (!first) {
    fmt::print(stderr, "vgc serve: {}\n", error);
    return 2;
  }
  const Route route = o.impl.route;
  h.make_node = [route, options](std::string* err) -> std::unique_ptr<verse::HostedNode> {
    std::unique_ptr<Implementation> impl = open_route(route, options, err);
    if (!impl) return nullptr;
    return std::make_unique<ImplementationNode>(std::move(impl));
  };
  h.log = [](const std::string& line) { fmt::print(stderr, "vgc serve --verse: {}\n", line); };
  verse::Host host;
  const verse::Status st = host.open(h);
  if (!st.ok()) {
    fmt::print(stderr, "vgc serve --verse: {}\n", st.to_string());
    return 2;
  }
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  fmt::print(stdout, "vgc-verse listening {}:{}\n", h.address, host.port());
  std::fflush(stdout);
  const verse::Status end = host.run(g_stop);
  if (!end.ok()) {
    fmt::print(stderr, "vgc serve --verse: {}\n", end.to_string());
    return 2;
  }
  return 0;
}

bool put(const std::string& s) {
  return std::fwrite(s.data(), 1, s.size(), stdout) == s.size() && std::fflush(stdout) == 0;
}

// A failure of the served implementation itself (only a plugin's
// ProtocolError can happen in process) is relayed as a line no request
// allows, so the suite on the other side records a ProtocolError too.
std::string failure_line(CallStatus s, const std::string& detail) {
  std::string d = detail;
  for (char& ch : d)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return std::string("vgc-serve-failure ") + call_status_name(s) + ": " + d + "\n";
}

std::string one_line(const std::string& s) {
  std::string d = s;
  for (char& ch : d)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return d;
}

std::string answer_line(Implementation& impl, const std::string& line, bool done) {
  if (line == "?hello") return "vgc-exec 1 " + one_line(impl.identity()) + "\n";
  if (line == "?reset") {
    const Answer a = impl.reset();
    return a.status == CallStatus::Ok ? "ok\n" : failure_line(a.status, a.detail);
  }
  if (line == "?snapshot" || line == "?derived") {
    const Document d = line == "?snapshot" ? impl.snapshot() : impl.derived();
    return d.status == CallStatus::Ok ? d.text : failure_line(d.status, d.detail);
  }
  if (line == "?digest") {
    if (!impl.offers_digest()) return "error unknown request ?digest\n";
    const DigestAnswer d = impl.digest();
    return d.status == CallStatus::Ok ? format_digest_line(d.digests) : failure_line(d.status, d.detail);
  }
  if (capability_document_header(line)) {
    Document d = impl.request(line);
    // The served implementation answers ?digest (docs/adapters.md): claimed
    // with the other capability words.
    if (d.status == CallStatus::Ok && line == "?capabilities" && impl.offers_digest() &&
        d.text.rfind("capabilities", 0) == 0)
      d.text.insert(d.text.find('\n'), " digest");
    if (d.status == CallStatus::Ok) return d.text;
    if (d.detail == "not supported") return "error unknown request " + one_line(line) + "\n";
    return failure_line(d.status, d.detail);
  }
  if (!line.empty() && line[0] == '?') return "error unknown request " + one_line(line) + "\n";
  Command c;
  bool blank = false;
  TextError e;
  if (!parse_command_line(line, 1, &c, &blank, &e)) {
    if (blank) return "error line 1, column 1: expected a command, found an empty line or a comment\n";
    return "error " + one_line(e.to_string()) + "\n";
  }
  const Answer a = impl.apply(c);
  if (a.status != CallStatus::Ok) return failure_line(a.status, a.detail);
  if (a.malformed) return "error " + one_line(a.detail) + "\n";
  if (done || !a.verdict_reported) return "done\n";
  if (a.applied) return "ok\n";
  return "rejected " + a.reason + "\n";
}

int run_serve(const ServeOptions& o) {
  if (!o.verse.empty()) return run_verse(o);
  OpenOptions options;
  options.isolate_plugin = false;  // we are the isolation
  std::string error;
  std::unique_ptr<Implementation> impl = open_route(o.impl.route, options, &error);
  if (!impl) {
    fmt::print(stderr, "vgc serve: {}\n", error);
    return 2;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "?quit") return 0;
    if (!put(answer_line(*impl, line, o.done))) return 3;
  }
  return 0;
}

void add_serve(CLI::App& app, int* exit_code) {
  auto opts = std::make_shared<ServeOptions>();
  CLI::App* sub = app.add_subcommand(
      "serve", "Serve a node over the exec protocol on stdin/stdout (docs/adapters.md)");
  add_impl_options(sub, &opts->impl, 0, "What to serve: reference (default) or plugin:PATH (loaded in this process)");
  auto* done = sub->add_flag("--done", opts->done,
                "Answer every command \"done\" (processed, verdict not reported), as a host on the Verse wire "
                "reports nothing (docs/adapters.md)");
  auto* verse = sub->add_option("--verse", opts->verse,
                  "Serve as a Verse r6 host on UDP [ADDR:]PORT (default address 127.0.0.1; PORT 0: any free "
                  "port); prints 'vgc-verse listening ADDR:PORT' (docs/verse_wire.md)");
  auto* like_r6 = sub->add_flag("--like-r6", opts->like_r6,
                "With --verse: behave as the r6 host does where a client must cope (a destroyed node's id is "
                "reused; bone_create in r6's form, a packet that does not decode losing its rest; "
                "docs/verse_wire.md)");
  like_r6->needs(verse);
  sub->add_option("--r6-deviation", opts->r6_deviations,
                  "With --verse: break the spec as the r6 host does, for testing a client that must find it: "
                  "announce-missing-deletes (a vertex_delete of a vertex that is not live is sent to "
                  "subscribers), xyz-no-default (a new subscriber is told def_real 0 for every VERTEX_XYZ layer), both-formats (a session that "
                  "subscribes REAL32 then REAL64 is sent every value in both); repeatable (docs/verse_wire.md)")
      ->check(CLI::IsMember({"announce-missing-deletes", "xyz-no-default", "both-formats"}))
      ->needs(verse);
  done->excludes(verse);  // a Verse host answers nothing: --done is the exec route's way to say so
  sub->callback([opts, exit_code] { *exit_code = run_serve(*opts); });
}

const Subcommand kServe{add_serve};

}  // namespace
}  // namespace vgc::cli
