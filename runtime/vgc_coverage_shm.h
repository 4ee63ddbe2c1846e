/* vgc_coverage_shm.h — the layout of the shared memory through which an
 * implementation built with clang's SanitizerCoverage shows vgc its
 * coverage counters: vgc creates the region, the runtime shipped with vgc
 * (vgc_coverage.c, linked into the implementation) maps the
 * implementation's counters into it, vgc reads and clears them around
 * each input.
 *
 * Spec: clang SanitizerCoverage, "Inline 8bit-counters" and "PC-Table"
 * (__sanitizer_cov_8bit_counters_init(start, stop) once per module,
 * __sanitizer_cov_pcs_init(beg, end): one {PC, flags} pair per counter,
 * flags bit 0 = the block is a function's entry); docs/fuzzing.md
 * "Coverage of the implementation". Layout version 2 adds the entries'
 * PCs, as offsets from their module's load address, so that vgc can name
 * the functions no input entered (`vgc fuzz --coverage-report`).
 *
 * Rationale: the counters are plain bytes the compiled code increments in
 * place, in a section of each module (__sancov_cntrs); the process does
 * not know where one input ends. So the runtime does not copy them: it
 * moves them. At start-up it copies each module's pages that hold
 * counters into a block of this region and maps the block over those
 * pages (MAP_SHARED | MAP_FIXED), so that the code's own increments land
 * in the shared memory and vgc sees them as soon as the implementation
 * has answered, with nothing to synchronise and no cost per input inside
 * the implementation. The name of the region is in the environment
 * variable VGC_COVERAGE_SHM (a POSIX shared memory name, "/vgc-..."),
 * which vgc sets for the process it starts; without it the runtime does
 * nothing. Bounded: vgc sizes the region for max_counters counters and
 * max_modules modules; a module past either is left unmapped and the
 * runtime says so once on stderr (dropped_counters counts them). Plain
 * C, fixed-width fields, no pointers: both sides may be any language.
 */
#ifndef VGC_COVERAGE_SHM_H
#define VGC_COVERAGE_SHM_H

#include <stdint.h>

#define VGC_COVERAGE_MAGIC "vgccov1"   /* 8 bytes with its NUL */
#define VGC_COVERAGE_ENV "VGC_COVERAGE_SHM"
#define VGC_COVERAGE_MAX_MODULES 30  /* the header fits one 4 KiB page */
#define VGC_COVERAGE_HEADER_BYTES 4096u /* the header area; block offsets are multiples of the system page */
#define VGC_COVERAGE_VERSION 2
#define VGC_COVERAGE_NO_PC 0xFFFFFFFFu

struct vgc_coverage_module {
  uint64_t block_offset;   /* where the module's pages are in the region (a multiple of the page size) */
  uint32_t counter_offset; /* where its first counter is inside that block */
  uint32_t counters;       /* how many */
  uint32_t first_index;    /* its counters' first global index (0 .. header.counters - 1) */
  uint32_t has_pcs;        /* 1 when __sanitizer_cov_pcs_init gave its PC table (flags area filled) */
  char path[104];          /* the module's file (dladdr), cut to 103 bytes */
};

struct vgc_coverage_header {
  char magic[8];           /* VGC_COVERAGE_MAGIC: written by vgc */
  uint32_t version;        /* VGC_COVERAGE_VERSION */
  uint32_t page_size;      /* the system page size vgc saw */
  uint32_t max_counters;   /* capacity of the flags area and of the blocks (vgc) */
  uint32_t max_modules;    /* <= VGC_COVERAGE_MAX_MODULES (vgc) */
  uint64_t flags_offset;   /* a byte per counter: 1 function entry, 0 not (or no PC table) */
  uint64_t pcs_offset;     /* 4 bytes per counter (native order): a function entry's PC minus its module's
                            * load address (dladdr's dli_fbase), VGC_COVERAGE_NO_PC for any other counter */
  uint64_t blocks_offset;  /* start of the blocks area */
  uint64_t region_size;    /* the whole region */
  /* Written by the runtime. owner_pid: the process whose counters are
   * mapped (0: none yet); a process that finds a live owner of another pid
   * leaves the region alone (a child the implementation started). */
  int32_t owner_pid;
  uint32_t modules;
  uint32_t counters;          /* counters mapped, all modules */
  uint32_t dropped_counters;  /* counters of modules that did not fit */
  uint64_t next_block;        /* the next free block offset */
  uint32_t function_entries;  /* counters whose PC-table flag says function entry */
  uint32_t generation;        /* incremented by each process that takes the region */
  struct vgc_coverage_module module[VGC_COVERAGE_MAX_MODULES];
};

#endif
