// asan_options.cpp — AddressSanitizer defaults of the libFuzzer targets.
//
// Spec: none (fuzzing practice; docs/fuzzing.md "Benchmark").
//
// Rationale: measured with perf on fuzz_stream and the property targets,
// half the CPU of a run went to ASan's allocator rather than to the code
// under test: each allocation recorded its stack (StackDepot), was filled
// with 0xbe up to 4 KB, and the 256 MB quarantine kept handing out fresh
// pages (page faults, clear_page). These defaults keep every check ASan
// makes (bounds, use after free within the last 16 MB freed, double free,
// leaks) and drop the allocation stacks from reports and the fill pattern:
//   quarantine_size_mb=16  max_malloc_fill_size=0  malloc_context_size=0
// ASAN_OPTIONS in the environment overrides them, e.g. to see where a
// reported chunk was allocated: ASAN_OPTIONS=malloc_context_size=30.
// Linked into the libFuzzer targets only (-DVGC_FUZZ=ON).
extern "C" const char* __asan_default_options() {
  return "quarantine_size_mb=16:max_malloc_fill_size=0:malloc_context_size=0";
}
