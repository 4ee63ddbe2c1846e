// running_host.h — a Verse host (verse/verse_host.h) on 127.0.0.1:<any free
// port>, served by a thread until destroyed: the fixture the verse tests
// share (session_test, host_follow_test, session_drop_test).
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "verse_host.h"

namespace vgc::verse {

struct RunningHost {
  Host host;
  std::atomic<bool> stop{false};
  std::thread thread;
  explicit RunningHost(HostOptions o = {}) {
    o.address = "127.0.0.1";
    o.port = 0;
    const Status st = host.open(o);
    EXPECT_TRUE(st.ok()) << st.to_string();
    thread = std::thread([this] { (void)host.run(stop); });
  }
  ~RunningHost() {
    stop = true;
    thread.join();
  }
};

}  // namespace vgc::verse
