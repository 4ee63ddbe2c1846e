// coverage_record.h — what a fuzz target saw of a running implementation's
// own coverage (coverage_region.h), written to a file for the campaign,
// which merges the files of all its processes (libFuzzer's rounds and
// fork-mode jobs are separate processes) into the summary's figures.
//
// Spec: docs/fuzzing.md "Coverage of the implementation" (the summary's
// "implementation coverage" line and summary.json's implementation_coverage).
//
// Rationale: a plain text file per process, rewritten whole (a temporary
// file renamed over it) when the reached counters grew and a second has
// passed, and at the end: a process that is killed at the campaign's
// deadline or aborts at a finding still leaves what it had a second
// before. Bounded: a record names at most 2^26 counters (the region's own
// bound), the maps are hex, parsed with std::from_chars.
//
//   vgc-implementation-coverage 1
//   mode guide|observe
//   seen 0|1
//   counters N
//   dropped N
//   function_entries N
//   module PATH (N counters, PC table)
//   timeline UNIX_TIME REACHED      (when this process's count grew; at most 200 lines)
//   reached HEX                     (bit i of the map: counter i reached)
//   entries HEX                     (bit i: counter i is a function's entry)
//   function INDEX MODULE OFFSET    (a function's entry counter, its module's number among the module
//                                    lines, its PC minus the module's load address in hex; at most
//                                    65,536 lines: for --coverage-report)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vgc::fuzz {

struct CoverageRecord {
  std::string mode;  // "guide" (folded into libFuzzer's features) or "observe" (only counted)
  bool seen = false;  // an implementation process mapped its counters
  std::size_t counters = 0, dropped = 0, function_entries = 0;
  std::vector<std::string> modules;
  std::vector<std::pair<double, std::size_t>> timeline;  // seconds since the epoch, counters reached by then
  std::vector<std::uint8_t> reached;  // one byte per counter, 1 = reached
  std::vector<std::uint8_t> entries;  // one byte per counter, 1 = a function's entry
  struct Function {
    std::size_t index = 0;
    std::size_t module = 0;
    std::uint32_t offset = 0;
  };
  std::vector<Function> functions;  // the entries whose PC is known
};

// A function of the implementation, for --coverage-report: where its code
// is and whether any input entered it.
struct ImplementationFunction {
  std::string module;         // the module's file
  std::uint32_t offset = 0;   // PC minus the module's load address
  bool entered = false;
};

// The campaign's view: every record of a run merged (counters reached by
// any process; the largest layout; timelines on the campaign's clock when
// the records' start offsets are given).
struct CoverageTotals {
  bool recorded = false;  // the target wrote records (a live implementation over exec)
  std::string mode;
  bool seen = false;
  std::size_t counters = 0, reached = 0, function_entries = 0, functions_entered = 0, dropped = 0;
  std::vector<std::string> modules;
  // (seconds since the epoch, the most counters any process had reached by
  // then), in time order.
  std::vector<std::pair<double, std::size_t>> timeline;
  std::vector<ImplementationFunction> functions;  // in counter order
};

// The file of a module line ("PATH (N counters, PC table)" -> "PATH").
std::string module_path(const std::string& module_line);

std::string format_coverage_record(const CoverageRecord& r);
// false and *error for anything that is not a record of this form.
bool parse_coverage_record(const std::string& text, CoverageRecord* out, std::string* error);
// Writes `r` to `path` atomically (PATH.tmp renamed over it). false on failure.
bool write_coverage_record(const std::string& path, const CoverageRecord& r);
// Every *.txt record under `dir`, merged; files that do not parse are skipped.
CoverageTotals merge_coverage_records(const std::string& dir);

}  // namespace vgc::fuzz
