/* vgc_coverage.c — the coverage runtime vgc ships for the implementations
 * it fuzzes (libvgc_coverage.a): an implementation compiled by clang with
 * -fsanitize-coverage=inline-8bit-counters (optionally ,pc-table) and
 * linked with it shows vgc the coverage of its own code while vgc fuzzes
 * it, through the shared memory named by VGC_COVERAGE_SHM.
 *
 * Spec: clang SanitizerCoverage, "Inline 8bit-counters" and "PC-Table"
 * (the two callbacks below, called by each instrumented module's
 * constructor); the region's layout is vgc_coverage_shm.h; docs/fuzzing.md
 * "Coverage of the implementation".
 *
 * Rationale (the design is in vgc_coverage_shm.h): each module's counter
 * pages are copied into a block of the region and the block is mapped over
 * them, so the implementation's own increments are vgc's to read. Only
 * what a constructor may do, and nothing that allocates: no stdio, no
 * malloc; messages go to fd 2 with write(2). Without VGC_COVERAGE_SHM it
 * does nothing at all, so the same binary runs normally outside vgc. Two
 * things a program may do are handled: forking (a child gets private
 * copies of the pages, so that parent and child share nothing they did
 * not share before: pthread_atfork), and starting another instrumented
 * program with the variable still set (the region has one owner, a live
 * process; another one leaves it alone). What is not handled is said in
 * docs/fuzzing.md: counters of a module loaded while other threads run
 * (dlopen mid-run) may lose a write to a variable sharing their page in
 * the instant of the copy.
 *
 * Linked, not preloaded: without a sanitizer the instrumented code needs
 * a definition of __sanitizer_cov_8bit_counters_init at link time, and
 * with AddressSanitizer its runtime's weak no-op definition is bound
 * inside the executable, where LD_PRELOAD cannot replace it. The symbols
 * are hidden, so a shared library (a plugin) keeps its own copy and
 * exports nothing more. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "vgc_coverage_shm.h"

#define VGC_HIDDEN __attribute__((visibility("hidden")))

_Static_assert(sizeof(struct vgc_coverage_header) <= VGC_COVERAGE_HEADER_BYTES, "the header fits its area");

/* dladdr is in libc from glibc 2.34 on, in libdl before: weak, so that the
 * runtime links without -ldl; a module's path is only a label. */
extern int dladdr(const void*, Dl_info*) __attribute__((weak));

/* This process's view: one per copy of the runtime (a plugin linking it
 * has its own). */
static int g_state;  /* 0 not tried, 1 attached, -1 off (no variable, or it failed) */
static int g_fd = -1;
static struct vgc_coverage_header* g_header;
static size_t g_page;
static struct {
  uintptr_t lo, hi;
  uint32_t module;  /* index in the header's table */
} g_mapped[VGC_COVERAGE_MAX_MODULES];
static int g_nmapped;
static int g_overflow_said;

static void say(const char* a, const char* b, const char* c) {
  const char* parts[4] = {"vgc_coverage: ", a, b, c};
  for (int i = 0; i < 4; ++i)
    if (parts[i]) {
      ssize_t ignored = write(2, parts[i], strlen(parts[i]));
      (void)ignored;
    }
  ssize_t ignored = write(2, "\n", 1);
  (void)ignored;
}

static const char* number(uint64_t v, char* buf /* 24 bytes */) {
  char* p = buf + 23;
  *p = '\0';
  do {
    *--p = (char)('0' + v % 10);
    v /= 10;
  } while (v);
  return p;
}

/* A forked child gets private copies of the pages (with their contents),
 * so that nothing the two processes keep in those pages is shared. */
static void private_copies_in_child(void) {
  for (int i = 0; i < g_nmapped; ++i) {
    const size_t len = g_mapped[i].hi - g_mapped[i].lo;
    void* lo = (void*)g_mapped[i].lo;
    void* copy = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (copy == MAP_FAILED) continue;
    memcpy(copy, lo, len);
    if (mmap(lo, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) != MAP_FAILED)
      memcpy(lo, copy, len);
    munmap(copy, len);
  }
  g_nmapped = 0;
  g_state = -1;
  if (g_header) munmap(g_header, VGC_COVERAGE_HEADER_BYTES);
  g_header = NULL;
  if (g_fd >= 0) close(g_fd);
  g_fd = -1;
}

/* Opens the region named by VGC_COVERAGE_SHM and takes it for this
 * process; g_state 1 on success, -1 (and said why, except when the
 * variable is unset) otherwise. */
static void attach(void) {
  g_state = -1;
  const char* name = getenv(VGC_COVERAGE_ENV);
  if (!name || !*name) return;
  char path[256] = "/dev/shm/";
  const char* base = name[0] == '/' ? name + 1 : name;
  if (strlen(base) + 10 > sizeof path || strchr(base, '/')) {
    say(VGC_COVERAGE_ENV "=", name, ": not a shared memory name; the coverage is not shown");
    return;
  }
  strcat(path, base);
  const int fd = open(path, O_RDWR | O_CLOEXEC);
  if (fd < 0) {
    say("cannot open the shared memory ", path, ": the coverage is not shown");
    return;
  }
  struct stat st;
  void* h = MAP_FAILED;
  if (fstat(fd, &st) == 0 && st.st_size >= (off_t)VGC_COVERAGE_HEADER_BYTES)
    h = mmap(NULL, VGC_COVERAGE_HEADER_BYTES, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (h == MAP_FAILED) {
    close(fd);
    say("the shared memory ", path, " is too small or cannot be mapped: the coverage is not shown");
    return;
  }
  struct vgc_coverage_header* hdr = (struct vgc_coverage_header*)h;
  const long page = sysconf(_SC_PAGESIZE);
  if (memcmp(hdr->magic, VGC_COVERAGE_MAGIC, 8) != 0 || hdr->version != VGC_COVERAGE_VERSION || hdr->page_size != (uint32_t)page ||
      hdr->region_size > (uint64_t)st.st_size || hdr->max_modules > VGC_COVERAGE_MAX_MODULES ||
      hdr->blocks_offset % (uint64_t)page != 0) {
    munmap(h, VGC_COVERAGE_HEADER_BYTES);
    close(fd);
    say("the shared memory ", path, " was not made by this vgc (layout version 2): the coverage is not shown");
    return;
  }
  /* One owner: a live process of another pid keeps it (this process is
   * something the implementation started with the variable inherited). */
  const int32_t me = (int32_t)getpid();
  int32_t owner = __atomic_load_n(&hdr->owner_pid, __ATOMIC_ACQUIRE);
  for (;;) {
    if (owner == me) break;
    if (owner != 0 && (kill(owner, 0) == 0 || errno != ESRCH)) {
      char buf[24];
      munmap(h, VGC_COVERAGE_HEADER_BYTES);
      close(fd);
      say("the shared memory is taken by process ", number((uint64_t)owner, buf),
          ": this process's coverage is not shown");
      return;
    }
    if (__atomic_compare_exchange_n(&hdr->owner_pid, &owner, me, 0, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
      hdr->modules = 0;
      hdr->counters = 0;
      hdr->dropped_counters = 0;
      hdr->function_entries = 0;
      hdr->next_block = 0;
      __atomic_add_fetch(&hdr->generation, 1, __ATOMIC_ACQ_REL);
      break;
    }
  }
  g_fd = fd;
  g_header = hdr;
  g_page = (size_t)page;
  g_state = 1;
  pthread_atfork(NULL, NULL, private_copies_in_child);
}

static void overflow(const char* what, uint64_t n) {
  if (g_overflow_said) return;
  g_overflow_said = 1;
  char buf[24];
  say(what, number(n, buf), " counters are not shown (vgc sized the shared memory for fewer)");
}

VGC_HIDDEN void __sanitizer_cov_8bit_counters_init(char* start, char* stop) {
  if (start == stop) return;
  if (g_state == 0) attach();
  if (g_state != 1) return;
  struct vgc_coverage_header* hdr = g_header;
  const uintptr_t lo = (uintptr_t)start & ~(uintptr_t)(g_page - 1);
  const uintptr_t hi = ((uintptr_t)stop + g_page - 1) & ~(uintptr_t)(g_page - 1);
  for (int i = 0; i < g_nmapped; ++i)
    if (lo < g_mapped[i].hi && g_mapped[i].lo < hi) return; /* this module again, or pages already shared */
  const uint64_t n = (uint64_t)(stop - start), len = hi - lo;
  if (hdr->modules >= hdr->max_modules || g_nmapped >= VGC_COVERAGE_MAX_MODULES) {
    hdr->dropped_counters += (uint32_t)n;
    overflow("too many instrumented modules: ", n);
    return;
  }
  if (hdr->counters + n > hdr->max_counters || hdr->blocks_offset + hdr->next_block + len > hdr->region_size) {
    hdr->dropped_counters += (uint32_t)n;
    overflow("a module past the region's size: its ", n);
    return;
  }
  const off_t where = (off_t)(hdr->blocks_offset + hdr->next_block);
  void* block = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_SHARED, g_fd, where);
  if (block == MAP_FAILED) {
    say("cannot map a block of the shared memory: ", strerror(errno), "");
    return;
  }
  memcpy(block, (void*)lo, len);
  void* placed = mmap((void*)lo, len, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_FIXED, g_fd, where);
  munmap(block, len);
  if (placed == MAP_FAILED) {
    say("cannot map the shared memory over the counters: ", strerror(errno), "");
    return;
  }
  struct vgc_coverage_module* m = &hdr->module[hdr->modules];
  memset(m, 0, sizeof *m);
  m->block_offset = hdr->next_block;
  m->counter_offset = (uint32_t)((uintptr_t)start - lo);
  m->counters = (uint32_t)n;
  m->first_index = hdr->counters;
  Dl_info info;
  if (dladdr && dladdr(start, &info) && info.dli_fname) {
    /* A relative name (the program as it was started, `./verse`) is made
     * absolute now, while the working directory is the one it was started
     * in: vgc names the module's functions from its file later, elsewhere.
     * A bare name found on PATH is the running program's own file. */
    const char* name = info.dli_fname;
    char full[4096];
    if (name[0] != '/') {
      if (realpath(name, full)) {
        name = full;
      } else {
        const ssize_t k = readlink("/proc/self/exe", full, sizeof full - 1);
        if (k > 0) {
          full[k] = '\0';
          name = full;
        }
      }
    }
    size_t len = strlen(name);
    if (len > sizeof m->path - 1) len = sizeof m->path - 1;
    memcpy(m->path, name, len);
    m->path[len] = '\0';
  }
  g_mapped[g_nmapped].lo = lo;
  g_mapped[g_nmapped].hi = hi;
  g_mapped[g_nmapped].module = hdr->modules;
  ++g_nmapped;
  hdr->next_block += len;
  hdr->counters += (uint32_t)n;
  /* Published last: vgc reads modules entries below this count only. */
  __atomic_store_n(&hdr->modules, hdr->modules + 1, __ATOMIC_RELEASE);
}

VGC_HIDDEN void __sanitizer_cov_pcs_init(const uintptr_t* beg, const uintptr_t* end) {
  if (g_state != 1 || beg >= end) return;
  struct vgc_coverage_header* hdr = g_header;
  const uint64_t n = (uint64_t)(end - beg) / 2;
  /* The module of this table: the constructor registers its counters
   * first, so it is the latest module of that size without a table. */
  for (int i = g_nmapped - 1; i >= 0; --i) {
    struct vgc_coverage_module* m = &hdr->module[g_mapped[i].module];
    if (m->has_pcs || m->counters != n) continue;
    uint8_t* flags = (uint8_t*)mmap(NULL, hdr->max_counters, PROT_READ | PROT_WRITE, MAP_SHARED, g_fd,
                                    (off_t)hdr->flags_offset);
    if (flags == MAP_FAILED) return;
    /* The entries' PCs as offsets from the module's load address. */
    const size_t pcs_len = (size_t)hdr->max_counters * 4;
    uint32_t* pcs = (uint32_t*)mmap(NULL, pcs_len, PROT_READ | PROT_WRITE, MAP_SHARED, g_fd, (off_t)hdr->pcs_offset);
    Dl_info info;
    const uintptr_t base =
        dladdr && n > 0 && dladdr((const void*)beg[0], &info) && info.dli_fbase ? (uintptr_t)info.dli_fbase : 0;
    uint32_t entries = 0;
    for (uint64_t k = 0; k < n; ++k) {
      const uint8_t entry = (uint8_t)(beg[2 * k + 1] & 1);
      flags[m->first_index + k] = entry;
      entries += entry;
      if (pcs != MAP_FAILED) {
        const uintptr_t pc = beg[2 * k];
        const int known = entry && base != 0 && pc >= base && pc - base < VGC_COVERAGE_NO_PC;
        pcs[m->first_index + k] = known ? (uint32_t)(pc - base) : VGC_COVERAGE_NO_PC;
      }
    }
    if (pcs != MAP_FAILED) munmap(pcs, pcs_len);
    munmap(flags, hdr->max_counters);
    m->has_pcs = 1;
    hdr->function_entries += entries;
    return;
  }
}
