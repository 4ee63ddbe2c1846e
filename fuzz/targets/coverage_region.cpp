// coverage_region.cpp — see coverage_region.h.
#include "coverage_region.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <filesystem>
#include <cstdlib>
#include <cstring>

#include "vgc_coverage_shm.h"

namespace vgc::fuzz {
namespace {

std::size_t round_up(std::size_t v, std::size_t to) { return (v + to - 1) / to * to; }

// Regions of fuzzer processes that are gone: a process that ends at a
// finding (abort) or is killed at the campaign's deadline cannot remove
// its own name. Only names of this form, only of processes that no longer
// exist.
void remove_stale_regions() {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/dev/shm", ec)) {
    const std::string n = e.path().filename().string();
    const std::string prefix = "vgc-coverage-";
    if (n.rfind(prefix, 0) != 0) continue;
    int pid = 0;
    const char* first = n.data() + prefix.size();
    const auto r = std::from_chars(first, n.data() + n.size(), pid);
    if (r.ec != std::errc() || r.ptr != n.data() + n.size() || pid <= 0) continue;
    if (kill(pid, 0) != 0 && errno == ESRCH) shm_unlink(("/" + n).c_str());
  }
}

}  // namespace

std::unique_ptr<CoverageRegion> CoverageRegion::create(std::size_t max_counters, std::string* error) {
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  max_counters = std::clamp<std::size_t>(max_counters, 1024, std::size_t{1} << 26);
  remove_stale_regions();
  std::unique_ptr<CoverageRegion> r(new CoverageRegion());
  r->name_ = "/vgc-coverage-" + std::to_string(getpid());
  int fd = shm_open(r->name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0 && errno == EEXIST) {
    // Left by a process of the same pid that is gone (this pid is ours now).
    shm_unlink(r->name_.c_str());
    fd = shm_open(r->name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  }
  if (fd < 0) {
    *error = "cannot create the shared memory " + r->name_ + ": " + std::strerror(errno);
    return nullptr;
  }
  r->fd_ = fd;
  // Header, a flag byte per counter, an entry's PC offset per counter, then
  // the blocks: every counter, and
  // two pages per module for the neighbours that share the counters' pages.
  const std::size_t header = round_up(VGC_COVERAGE_HEADER_BYTES, page);
  const std::size_t flags = round_up(max_counters, page);
  const std::size_t pcs = round_up(max_counters * 4, page);
  const std::size_t blocks = round_up(max_counters, page) + 2 * page * VGC_COVERAGE_MAX_MODULES;
  r->size_ = header + flags + pcs + blocks;
  if (ftruncate(fd, static_cast<off_t>(r->size_)) != 0) {
    *error = "cannot size the shared memory " + r->name_ + ": " + std::strerror(errno);
    return nullptr;  // the destructor unlinks it
  }
  void* p = mmap(nullptr, r->size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (p == MAP_FAILED) {
    *error = "cannot map the shared memory " + r->name_ + ": " + std::strerror(errno);
    return nullptr;
  }
  r->base_ = static_cast<std::uint8_t*>(p);
  r->header_ = reinterpret_cast<vgc_coverage_header*>(p);
  vgc_coverage_header& h = *r->header_;
  h.version = VGC_COVERAGE_VERSION;
  h.page_size = static_cast<std::uint32_t>(page);
  h.max_counters = static_cast<std::uint32_t>(max_counters);
  h.max_modules = VGC_COVERAGE_MAX_MODULES;
  h.flags_offset = header;
  h.pcs_offset = header + flags;
  h.blocks_offset = header + flags + pcs;
  h.region_size = r->size_;
  std::memcpy(h.magic, VGC_COVERAGE_MAGIC, 8);  // last: the runtime checks it first
  r->reached_.assign(max_counters, 0);
  setenv(VGC_COVERAGE_ENV, r->name_.c_str(), 1);
  return r;
}

CoverageRegion::~CoverageRegion() {
  if (base_) munmap(base_, size_);
  if (fd_ >= 0) {
    close(fd_);
    shm_unlink(name_.c_str());
  }
  if (const char* v = std::getenv(VGC_COVERAGE_ENV); v && name_ == v) unsetenv(VGC_COVERAGE_ENV);
}

bool CoverageRegion::attached() const {
  const std::int32_t owner = __atomic_load_n(&header_->owner_pid, __ATOMIC_ACQUIRE);
  return owner != 0 && __atomic_load_n(&header_->modules, __ATOMIC_ACQUIRE) > 0;
}

std::size_t CoverageRegion::counters() const { return __atomic_load_n(&header_->counters, __ATOMIC_ACQUIRE); }
std::size_t CoverageRegion::dropped_counters() const { return header_->dropped_counters; }
std::size_t CoverageRegion::function_entries() const { return header_->function_entries; }

std::vector<std::string> CoverageRegion::modules() const {
  std::vector<std::string> out;
  const std::uint32_t n = std::min<std::uint32_t>(__atomic_load_n(&header_->modules, __ATOMIC_ACQUIRE),
                                                  VGC_COVERAGE_MAX_MODULES);
  for (std::uint32_t i = 0; i < n; ++i) {
    const vgc_coverage_module& m = header_->module[i];
    const std::string path(m.path, strnlen(m.path, sizeof m.path));
    out.push_back((path.empty() ? "?" : path) + " (" + std::to_string(m.counters) + " counters" +
                  (m.has_pcs ? ", PC table" : "") + ")");
  }
  return out;
}

// The runtime writes the module table before it publishes the count, and
// only grows it; a table a new process is rewriting (generation changed)
// is read as it is: at worst one input's counters are attributed wrong.
void CoverageRegion::clear() {
  const std::uint32_t n = std::min<std::uint32_t>(__atomic_load_n(&header_->modules, __ATOMIC_ACQUIRE),
                                                  VGC_COVERAGE_MAX_MODULES);
  for (std::uint32_t i = 0; i < n; ++i) {
    const vgc_coverage_module& m = header_->module[i];
    const std::size_t at = header_->blocks_offset + m.block_offset + m.counter_offset;
    if (at + m.counters > size_) continue;
    std::memset(base_ + at, 0, m.counters);
  }
}

bool CoverageRegion::collect(std::uint8_t* out, std::size_t slots, bool counts) {
  bool grew = false;
  const std::uint32_t n = std::min<std::uint32_t>(__atomic_load_n(&header_->modules, __ATOMIC_ACQUIRE),
                                                  VGC_COVERAGE_MAX_MODULES);
  for (std::uint32_t i = 0; i < n; ++i) {
    const vgc_coverage_module& m = header_->module[i];
    const std::size_t at = header_->blocks_offset + m.block_offset + m.counter_offset;
    if (at + m.counters > size_ || std::size_t{m.first_index} + m.counters > reached_.size()) continue;
    const std::uint8_t* c = base_ + at;
    std::size_t k = 0;
    // Eight counters at a time: most are zero.
    for (; k < m.counters; ++k) {
      if ((k & 7) == 0 && k + 8 <= m.counters) {
        std::uint64_t word;
        std::memcpy(&word, c + k, 8);
        if (word == 0) {
          k += 7;
          continue;
        }
      }
      const std::uint8_t v = c[k];
      if (!v) continue;
      const std::size_t index = m.first_index + k;
      if (!reached_[index]) {
        reached_[index] = 1;
        ++reached_count_;
        grew = true;
      }
      if (out) {
        std::uint8_t& slot = out[index % slots];
        if (!counts) slot = 1;
        else if (v > slot) slot = v;
      }
    }
  }
  return grew;
}

std::vector<std::uint8_t> CoverageRegion::entry_map() const {
  const std::size_t n = std::min<std::size_t>(counters(), reached_.size());
  const std::uint8_t* flags = base_ + header_->flags_offset;
  return std::vector<std::uint8_t>(flags, flags + n);
}

std::size_t CoverageRegion::functions_entered() const {
  const std::size_t n = std::min<std::size_t>(counters(), reached_.size());
  const std::uint8_t* flags = base_ + header_->flags_offset;
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) k += flags[i] && reached_[i];
  return k;
}

}  // namespace vgc::fuzz

namespace vgc::fuzz {

std::vector<FunctionEntry> CoverageRegion::function_entry_list() const {
  std::vector<FunctionEntry> out;
  const std::uint32_t n = std::min<std::uint32_t>(__atomic_load_n(&header_->modules, __ATOMIC_ACQUIRE),
                                                  VGC_COVERAGE_MAX_MODULES);
  const std::uint8_t* flags = base_ + header_->flags_offset;
  for (std::uint32_t i = 0; i < n; ++i) {
    const vgc_coverage_module& m = header_->module[i];
    if (!m.has_pcs) continue;
    for (std::size_t k = 0; k < m.counters; ++k) {
      const std::size_t index = std::size_t{m.first_index} + k;
      if (index >= reached_.size() || !flags[index]) continue;
      std::uint32_t pc;
      std::memcpy(&pc, base_ + header_->pcs_offset + 4 * index, 4);
      if (pc == VGC_COVERAGE_NO_PC) continue;
      out.push_back({index, i, pc});
      if (out.size() >= kMaxFunctionEntries) return out;
    }
  }
  return out;
}

}  // namespace vgc::fuzz
