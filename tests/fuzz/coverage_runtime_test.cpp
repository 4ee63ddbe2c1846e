// coverage_runtime_test.cpp — vgc's coverage runtime (runtime/vgc_coverage.c)
// against the region the fuzz target makes (fuzz/targets/coverage_region.h), and
// the record the campaign reads (fuzz/targets/coverage_record.h).
//
// Spec: runtime/vgc_coverage_shm.h; docs/fuzzing.md "Coverage of the
// implementation".
//
// The compiler is not needed to test the runtime: a module's constructor
// only calls __sanitizer_cov_8bit_counters_init(start, stop) and
// __sanitizer_cov_pcs_init(beg, end), so the tests call them on arrays of
// their own, laid out as a module's counters are (sharing their pages with
// other data). The runtime attaches once per process: each scenario runs in
// a child process of its own.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>

#include "coverage_record.h"
#include "coverage_region.h"

extern "C" void __sanitizer_cov_8bit_counters_init(char* start, char* stop);
extern "C" void __sanitizer_cov_pcs_init(const std::uintptr_t* beg, const std::uintptr_t* end);

namespace {

using vgc::fuzz::CoverageRegion;

// Three pages: "neighbour" data before and after 5,000 counters at offset 100.
alignas(4096) std::uint8_t g_module[3 * 4096];
constexpr std::size_t kFirst = 100, kCounters = 5000;
std::uintptr_t g_pcs[2 * kCounters];

char* counters_begin() { return reinterpret_cast<char*>(g_module + kFirst); }
char* counters_end() { return reinterpret_cast<char*>(g_module + kFirst + kCounters); }

// Runs f in a child process; its exit code (f's return value), -1 on a signal.
int in_child(const std::function<int()>& f) {
  std::fflush(nullptr);
  const pid_t p = fork();
  if (p == 0) _exit(f());
  int status = 0;
  waitpid(p, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::unique_ptr<CoverageRegion> make_region(std::size_t max_counters) {
  std::string error;
  auto r = CoverageRegion::create(max_counters, &error);
  EXPECT_TRUE(r) << error;
  return r;
}

// Each check in a child is a distinct exit code, so that a failure says which.
#define CHILD_CHECK(cond, code) \
  do {                          \
    if (!(cond)) return code;   \
  } while (0)

TEST(CoverageRuntime, WithoutTheVariableItDoesNothing) {
  unsetenv("VGC_COVERAGE_SHM");
  EXPECT_EQ(0, in_child([] {
    g_module[0] = 42;
    __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end());
    g_module[kFirst + 3] = 1;
    CHILD_CHECK(g_module[0] == 42 && g_module[kFirst + 3] == 1, 1);
    return 0;
  }));
}

TEST(CoverageRuntime, TheRegionSeesTheCountersAndClearsThem) {
  EXPECT_EQ(0, in_child([] {
    auto region = make_region(1 << 16);
    CHILD_CHECK(region && std::getenv("VGC_COVERAGE_SHM") == region->name(), 1);
    CHILD_CHECK(!region->attached(), 2);
    g_module[0] = 42;                         // a neighbour before the counters
    g_module[kFirst + kCounters + 10] = 43;   // and after them
    g_module[kFirst + 1] = 7;                 // a counter already counted in a constructor
    for (std::size_t i = 0; i < kCounters; ++i) {
      g_pcs[2 * i] = 0x1000 + i;
      g_pcs[2 * i + 1] = i % 10 == 0 ? 1 : 0;  // every tenth block a function's entry
    }
    __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end());
    __sanitizer_cov_pcs_init(g_pcs, g_pcs + 2 * kCounters);
    CHILD_CHECK(region->attached() && region->counters() == kCounters, 3);
    CHILD_CHECK(region->function_entries() == kCounters / 10 && region->dropped_counters() == 0, 4);
    CHILD_CHECK(g_module[0] == 42 && g_module[kFirst + kCounters + 10] == 43 && g_module[kFirst + 1] == 7, 5);
    // The module's own increments land in the region.
    region->clear();
    CHILD_CHECK(g_module[kFirst + 1] == 0 && g_module[0] == 42, 6);  // cleared: only the counters
    g_module[kFirst + 20] = 3;
    g_module[kFirst + 20 + 64] = 9;  // the same slot of 64
    g_module[kFirst + 4999] = 1;
    std::uint8_t out[64] = {};
    CHILD_CHECK(region->collect(out, 64, /*counts=*/true), 7);
    CHILD_CHECK(region->reached() == 3 && out[20] == 9 && out[4999 % 64] == 1, 8);
    std::uint8_t edges[64] = {};  // the default: whether an edge was taken, not how often
    region->collect(edges, 64);
    CHILD_CHECK(edges[20] == 1 && edges[4999 % 64] == 1 && edges[21] == 0, 15);
    CHILD_CHECK(region->functions_entered() == 1, 9);  // counter 20 is an entry, 84 and 4999 are not
    CHILD_CHECK(!region->collect(out, 64), 10);        // nothing new
    region->clear();
    CHILD_CHECK(g_module[kFirst + 20] == 0 && g_module[kFirst + 4999] == 0, 11);
    // A forked child gets private pages: its counts and data are its own.
    const int child = in_child([] {
      g_module[kFirst + 30] = 1;
      g_module[0] = 99;
      return 0;
    });
    CHILD_CHECK(child == 0, 12);
    CHILD_CHECK(g_module[kFirst + 30] == 0 && g_module[0] == 42, 13);
    CHILD_CHECK(!region->collect(out, 64), 14);
    return 0;
  }));
}

TEST(CoverageRuntime, ALiveOwnerKeepsTheRegionADeadOneDoesNot) {
  EXPECT_EQ(0, in_child([] {
    auto region = make_region(1 << 16);
    CHILD_CHECK(region, 6);
    // A first process attaches and stays alive until told.
    int go[2];
    int ready[2];
    CHILD_CHECK(pipe(go) == 0 && pipe(ready) == 0, 1);
    std::fflush(nullptr);
    const pid_t owner = fork();
    if (owner == 0) {
      __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end());
      char c = 1;
      if (write(ready[1], &c, 1) != 1) _exit(1);
      if (read(go[0], &c, 1) < 0) _exit(1);
      _exit(0);
    }
    char c = 0;
    const bool attached = read(ready[0], &c, 1) == 1 && region->attached();
    // Another process with the same variable (a program the implementation
    // started) leaves it alone: its counters are not mapped.
    const int second = in_child([] {
      __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end() - 1000);
      return 0;
    });
    const std::size_t counters_then = region->counters();
    // Once the owner is gone (told to end whatever happened above, so that
    // a failure leaves no process behind), a new process takes it over (a restart).
    const bool told = write(go[1], &c, 1) == 1;
    waitpid(owner, nullptr, 0);
    CHILD_CHECK(attached, 2);
    CHILD_CHECK(second == 0 && counters_then == kCounters, 3);
    CHILD_CHECK(told, 4);
    const int third = in_child([] {
      __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end() - 1000);
      return 0;
    });
    CHILD_CHECK(third == 0 && region->counters() == kCounters - 1000, 5);
    return 0;
  }));
}

TEST(CoverageRuntime, AModulePastTheRegionsSizeIsDroppedAndCounted) {
  EXPECT_EQ(0, in_child([] {
    auto region = make_region(1024);  // fewer than the module's 5,000
    CHILD_CHECK(region, 3);
    __sanitizer_cov_8bit_counters_init(counters_begin(), counters_end());
    CHILD_CHECK(!region->attached() && region->counters() == 0, 1);
    CHILD_CHECK(region->dropped_counters() == kCounters, 2);
    g_module[kFirst] = 1;  // still the module's own memory
    return 0;
  }));
}

TEST(CoverageRecord, RoundTripAndMerge) {
  vgc::fuzz::CoverageRecord r;
  r.mode = "guide";
  r.seen = true;
  r.counters = 9;
  r.function_entries = 2;
  r.modules = {"/x/libhost.so (9 counters, PC table)"};
  r.timeline = {{1795777945.5, 3}, {1795777947.0, 4}};
  r.reached = {1, 0, 0, 1, 0, 1, 0, 0, 1};
  r.entries = {1, 0, 0, 0, 1, 0, 0, 0, 0};
  r.functions = {{0, 0, 0x1a30}, {4, 0, 0x2f00}};  // the two entries' PCs (--coverage-report)
  const std::string text = vgc::fuzz::format_coverage_record(r);
  vgc::fuzz::CoverageRecord back;
  std::string error;
  ASSERT_TRUE(vgc::fuzz::parse_coverage_record(text, &back, &error)) << error;
  EXPECT_EQ(back.reached, r.reached);
  EXPECT_EQ(back.entries, r.entries);
  EXPECT_EQ(back.modules, r.modules);
  EXPECT_EQ(back.timeline.size(), 2u);
  ASSERT_EQ(back.functions.size(), 2u);
  EXPECT_EQ(back.functions[1].index, 4u);
  EXPECT_EQ(back.functions[1].offset, 0x2f00u);
  EXPECT_EQ(vgc::fuzz::format_coverage_record(back), text);
  EXPECT_FALSE(vgc::fuzz::parse_coverage_record("vgc-implementation-coverage 1\nfunction 4 0 zz\n", &back, &error));
  // Bad records are refused, not guessed at.
  EXPECT_FALSE(vgc::fuzz::parse_coverage_record("vgc-implementation-coverage 2\n", &back, &error));
  EXPECT_FALSE(vgc::fuzz::parse_coverage_record(
      "vgc-implementation-coverage 1\ncounters 9\nreached 99\n", &back, &error));  // 2 digits for 9 counters
  EXPECT_FALSE(vgc::fuzz::parse_coverage_record("vgc-implementation-coverage 1\ncounters x\n", &back, &error));
  // Two processes' records merge to the union.
  const std::string dir = testing::TempDir() + "/coverage_records";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(vgc::fuzz::write_coverage_record(dir + "/1.txt", r));
  vgc::fuzz::CoverageRecord r2 = r;
  r2.reached = {0, 1, 0, 1, 0, 0, 0, 0, 0};
  ASSERT_TRUE(vgc::fuzz::write_coverage_record(dir + "/2.txt", r2));
  const vgc::fuzz::CoverageTotals t = vgc::fuzz::merge_coverage_records(dir);
  EXPECT_TRUE(t.recorded && t.seen);
  EXPECT_EQ(t.counters, 9u);
  EXPECT_EQ(t.reached, 5u);
  EXPECT_EQ(t.function_entries, 2u);
  EXPECT_EQ(t.functions_entered, 1u);
  // Each function once, with its module's file and whether any process entered it.
  ASSERT_EQ(t.functions.size(), 2u);
  EXPECT_EQ(t.functions[0].module, "/x/libhost.so");
  EXPECT_TRUE(t.functions[0].entered);    // counter 0: reached by the first process
  EXPECT_FALSE(t.functions[1].entered);   // counter 4: by neither
  EXPECT_EQ(t.functions[1].offset, 0x2f00u);
}

}  // namespace
