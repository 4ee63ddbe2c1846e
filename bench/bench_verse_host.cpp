// bench_verse_host.cpp — not a test: how long a Verse host takes to store a
// real mesh sent over loopback and show it to a subscriber (issue 28 item 5:
// "building the bunny's commands through it over loopback takes seconds").
//
// Spec: docs/verse_wire.md sections 5 (the window, acks), 7 (what a host
// sends subscribers) and 9 (`vgc serve --verse`; verse/followed_node.h for
// the cost per command).
//
// Usage: bench_verse_host [--repeats R] [--whole] [--host ADDR:PORT] MESH...
//
// Per mesh, the median of R runs (default 3) of: a driver session logs in,
// creates a geometry node and sends the mesh's commands (vgc import's, the
// vertices then the faces) in bursts of 32 (about a packet), reading the
// host's acks between bursts, as fast as the window lets it; an observer
// session subscribed to the node and to layers 0 and 1 (REAL64) reads what
// the host broadcasts on a thread of its own. The time is from the first
// command sent until the observer has seen one broadcast per command and
// the driver's barrier came back. The host is vgc's, in this process on a
// thread (the reference node, followed by its digest), or with --whole a
// reference node that offers no digest (read whole after every command:
// the host before issue 28), or with --host any running host (vgc serve
// --verse with any --impl, r6's `verse`). Wall times on a shared machine.
#include "bench_args.h"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "mesh_import.h"
#include "node.h"
#include "snapshot.h"
#include "verse_client.h"
#include "verse_host.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kWait = 600.0;  // seconds any one wait may take

// The reference without a digest: read whole after every command.
class WholeReadNode : public vgc::verse::HostedNode {
 public:
  bool apply(const vgc::Command& c, std::string*) override {
    node_.apply(c);
    return true;
  }
  bool snapshot(std::string* text, std::string*) override {
    *text = vgc::print_snapshot(node_);
    return true;
  }

 private:
  vgc::Node node_;
};

struct Target {
  std::string address = "127.0.0.1";
  std::uint16_t port = 0;
};

// One run; seconds, or a negative number after saying what went wrong.
double run_once(const Target& t, const std::vector<vgc::Command>& commands) {
  using namespace vgc::verse;
  ClientSession driver, observer;
  Status st = driver.connect(t.address, t.port, {});
  if (st.ok()) st = observer.connect(t.address, t.port, {});
  std::uint32_t node = 0;
  if (st.ok()) st = driver.create_geometry_node(&node, kWait);
  if (st.ok()) st = driver.subscribe_node(node);  // for its barrier's echo
  if (st.ok()) st = observer.subscribe_node(node);
  if (st.ok()) st = observer.subscribe_layer(node, 0, vgc::RealFormat::Real64);
  if (st.ok()) st = observer.subscribe_layer(node, 1, vgc::RealFormat::Real64);
  std::vector<WireCommand> seen;
  if (st.ok()) st = observer.barrier(node, kWait, &seen);
  if (!st.ok()) {
    std::fprintf(stderr, "bench_verse_host: setting up: %s\n", st.to_string().c_str());
    return -1;
  }
  std::atomic<std::size_t> broadcasts{0};
  std::atomic<bool> observer_failed{false};
  std::thread watch([&] {
    WireCommand w;
    const auto deadline = Clock::now() + std::chrono::seconds(static_cast<int>(kWait));
    while (broadcasts < commands.size() && Clock::now() < deadline) {
      const Status r = observer.receive(&w, 1.0);
      if (r.code == Status::Code::Timeout) continue;
      if (!r.ok()) {
        std::fprintf(stderr, "bench_verse_host: observer: %s\n", r.to_string().c_str());
        observer_failed = true;
        return;
      }
      if (const auto* g = std::get_if<wire::Geometry>(&w))
        if (g->node_id == node && (std::holds_alternative<vgc::cmd::VertexSetXyzReal64>(g->command) ||
                                   std::holds_alternative<vgc::cmd::PolygonSetCornerUint32>(g->command)))
          ++broadcasts;
    }
  });
  const auto t0 = Clock::now();
  // In bursts of 32 (a packet's worth), as a client flushes what it has,
  // reading what has arrived between them (the host's acks open the window).
  for (std::size_t i = 0; i < commands.size() && st.ok(); i += 32) {
    std::vector<WireCommand> burst;
    for (std::size_t k = i; k < std::min(commands.size(), i + 32); ++k) burst.push_back(wire::Geometry{node, commands[k]});
    st = driver.send_burst(burst);
    WireCommand ignored;
    while (st.ok() && driver.receive(&ignored, 0).ok()) {
    }
  }
  if (st.ok()) st = driver.barrier(node, kWait, &seen);
  watch.join();
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!st.ok() || observer_failed || broadcasts != commands.size()) {
    std::fprintf(stderr, "bench_verse_host: %s; the observer saw %zu of %zu broadcasts\n",
                 st.ok() ? "ok" : st.to_string().c_str(), broadcasts.load(), commands.size());
    return -1;
  }
  driver.disconnect();
  observer.disconnect();
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  bool whole = false;
  std::string external;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeats" && i + 1 < argc) repeats = static_cast<int>(vgc::bench::count_argument("bench_verse_host", "--repeats", argv[++i], 1, 1000));
    else if (a == "--whole") whole = true;
    else if (a == "--host" && i + 1 < argc) external = argv[++i];
    else meshes.push_back(a);
  }
  if (meshes.empty() || repeats < 1 || (whole && !external.empty())) {
    std::fprintf(stderr, "usage: bench_verse_host [--repeats R] [--whole | --host ADDR:PORT] MESH...\n");
    return 2;
  }
  Target target;
  std::unique_ptr<vgc::verse::Host> host;
  std::atomic<bool> stop{false};
  std::thread serving;
  std::string route = whole ? "vgc host, whole reads" : "vgc host, followed";
  if (!external.empty()) {
    std::string error;
    if (!vgc::verse::parse_listen_address(external, &target.address, &target.port, &error)) {
      std::fprintf(stderr, "bench_verse_host: --host %s\n", error.c_str());
      return 2;
    }
    route = "host " + external;
  } else {
    vgc::verse::HostOptions o;
    o.port = 0;
    if (whole)
      o.make_node = [](std::string*) -> std::unique_ptr<vgc::verse::HostedNode> {
        return std::make_unique<WholeReadNode>();
      };
    host = std::make_unique<vgc::verse::Host>();
    const vgc::verse::Status st = host->open(o);
    if (!st.ok()) {
      std::fprintf(stderr, "bench_verse_host: %s\n", st.to_string().c_str());
      return 2;
    }
    target.port = host->port();
    serving = std::thread([&] { (void)host->run(stop); });
  }
  std::printf("%-24s %8s %8s %9s  %-24s %8s %9s  (median of %d)\n", "mesh", "vertices", "faces", "commands", "route",
              "seconds", "us/cmd", repeats);
  int rc = 0;
  for (const std::string& path : meshes) {
    vgc::MeshProgram mesh;
    vgc::MeshFileError error;
    if (!vgc::import_mesh(path, vgc::MeshImportOptions{true}, &mesh, &error)) {
      std::fprintf(stderr, "%s:%zu: %s\n", path.c_str(), error.line, error.message.c_str());
      rc = 1;
      continue;
    }
    const auto& commands = mesh.program.commands;
    std::vector<double> t;
    for (int r = 0; r < repeats; ++r) {
      const double s = run_once(target, commands);
      if (s < 0) break;
      t.push_back(s);
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    if (t.size() != static_cast<std::size_t>(repeats)) {
      std::printf("%-24s %8zu %8zu %9zu  %-24s failed\n", name.c_str(), mesh.vertices, mesh.triangles + mesh.quads,
                  commands.size(), route.c_str());
      rc = 1;
      continue;
    }
    std::sort(t.begin(), t.end());
    const double m = t[t.size() / 2];
    std::printf("%-24s %8zu %8zu %9zu  %-24s %8.2f %9.1f\n", name.c_str(), mesh.vertices, mesh.triangles + mesh.quads,
                commands.size(), route.c_str(), m, 1e6 * m / static_cast<double>(commands.size()));
    std::fflush(stdout);
  }
  stop = true;
  if (serving.joinable()) serving.join();
  return rc;
}
