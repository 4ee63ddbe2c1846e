// serve_verse_test.cpp — `vgc serve --verse 0` as a user runs it: the
// program prints the port it bound, a client logs in over loopback, and a
// seeded fault of the fault plugin (VGC_FAULT) is visible through the wire
// where the plain reference is not faulty (docs/verse_wire.md section 9).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "verse_client.h"

namespace vgc::verse {
namespace {

// A `vgc serve --verse 0 ...` child; reads its "vgc-verse listening" line.
struct Served {
  pid_t pid = -1;
  std::uint16_t port = 0;
  std::string first_line;

  Served(const std::string& impl, const std::string& fault) {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid = fork();
    if (pid == 0) {
      dup2(fds[1], 1);
      close(fds[0]);
      close(fds[1]);
      if (!fault.empty()) setenv("VGC_FAULT", fault.c_str(), 1);
      execl(VGC_BINARY, VGC_BINARY, "serve", "--verse", "0", "--impl", impl.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (first_line.find('\n') == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      pollfd p{fds[0], POLLIN, 0};
      if (poll(&p, 1, 200) <= 0) continue;
      char c;
      if (read(fds[0], &c, 1) != 1) break;
      first_line += c;
    }
    close(fds[0]);
    const std::string prefix = "vgc-verse listening 127.0.0.1:";
    if (first_line.rfind(prefix, 0) == 0) port = static_cast<std::uint16_t>(std::stoi(first_line.substr(prefix.size())));
  }
  // SIGTERM; the exit status (-1 when it had to be killed).
  int stop() {
    if (pid <= 0) return -1;
    kill(pid, SIGTERM);
    for (int i = 0; i < 100; ++i) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    pid = -1;
    return -1;
  }
  ~Served() { stop(); }
};

// Makes a triangle, deletes it, and says whether the delete came back.
bool polygon_delete_seen(std::uint16_t port) {
  ClientSession s;
  Status st = s.connect("127.0.0.1", port, {});
  EXPECT_TRUE(st.ok()) << st.to_string();
  std::uint32_t node = 0;
  st = s.create_geometry_node(&node, 10);
  EXPECT_TRUE(st.ok()) << st.to_string();
  EXPECT_TRUE(s.subscribe_node(node).ok());
  EXPECT_TRUE(s.subscribe_layer(node, 1, RealFormat::Real64).ok());
  for (std::uint32_t v = 0; v < 3; ++v)
    EXPECT_TRUE(s.send_geometry(node, cmd::VertexSetXyzReal64{0, v, double(v), 1, 0}).ok());
  EXPECT_TRUE(s.send_geometry(node, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}}).ok());
  EXPECT_TRUE(s.send_geometry(node, cmd::PolygonDelete{0}).ok());
  std::vector<WireCommand> seen;
  st = s.barrier(node, 10, &seen);
  EXPECT_TRUE(st.ok()) << st.to_string();
  bool created = false, deleted = false;
  for (const WireCommand& c : seen)
    if (const auto* g = std::get_if<wire::Geometry>(&c)) {
      created = created || std::holds_alternative<cmd::PolygonSetCornerUint32>(g->command);
      deleted = deleted || std::holds_alternative<cmd::PolygonDelete>(g->command);
    }
  EXPECT_TRUE(created);
  return deleted;
}

TEST(VgcServeVerse, ServesTheReferenceAndShowsASeededFault) {
  Served reference("reference", "");
  ASSERT_NE(reference.port, 0) << "first line: " << reference.first_line;
  EXPECT_TRUE(polygon_delete_seen(reference.port));
  EXPECT_EQ(reference.stop(), 0) << "SIGTERM ends the server with exit 0";

  Served faulty(std::string("plugin:") + VGC_FAULT_PLUGIN, "polygon-delete-ignored");
  ASSERT_NE(faulty.port, 0) << "first line: " << faulty.first_line;
  EXPECT_FALSE(polygon_delete_seen(faulty.port)) << "the fault plugin keeps the polygon";
  EXPECT_EQ(faulty.stop(), 0);
}

TEST(VgcServeVerse, ABadAddressIsAUsageError) {
  const std::string cmd = std::string(VGC_BINARY) + " serve --verse 70000 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

}  // namespace
}  // namespace vgc::verse
