// replay_main.cpp — a libFuzzer-compatible driver without libFuzzer.
//
// Spec: none (tooling). docs/fuzzing.md "Replay".
//
// Rationale: the normal build (g++, `./vgc test`) has no libFuzzer, yet every
// corpus file and every crash ever fixed must keep being run through every
// target. This main runs LLVMFuzzerInitialize (when the target defines it)
// and then LLVMFuzzerTestOneInput once per file. Arguments naming a
// directory mean every regular file in it, in name order (so runs are
// reproducible); arguments starting with '-' are ignored, so the same
// command line works for a libFuzzer binary given -runs=0. A target reports
// a finding by aborting, exactly as under libFuzzer.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {

bool read_file(const std::filesystem::path& p, std::string* out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!arg.empty() && arg[0] == '-') continue;
    std::error_code ec;
    if (std::filesystem::is_directory(arg, ec)) {
      std::vector<std::filesystem::path> inside;
      for (const auto& e : std::filesystem::directory_iterator(arg))
        if (e.is_regular_file()) inside.push_back(e.path());
      std::sort(inside.begin(), inside.end());
      files.insert(files.end(), inside.begin(), inside.end());
    } else if (std::filesystem::is_regular_file(arg, ec)) {
      files.emplace_back(arg);
    } else {
      std::fprintf(stderr, "replay: %s: no such file or directory\n", arg.c_str());
      return 2;
    }
  }
  std::size_t bytes = 0;
  for (const auto& f : files) {
    std::string data;
    if (!read_file(f, &data)) {
      std::fprintf(stderr, "replay: cannot read %s\n", f.string().c_str());
      return 2;
    }
    std::fprintf(stderr, "replay: %s\n", f.string().c_str());
    // A copy in its own allocation, so reads past the end are caught by
    // ASan or valgrind as they would be under libFuzzer.
    std::vector<std::uint8_t> copy(data.begin(), data.end());
    LLVMFuzzerTestOneInput(copy.empty() ? nullptr : copy.data(), copy.size());
    bytes += data.size();
  }
  std::fprintf(stdout, "replay: %zu inputs, %zu bytes, no finding\n", files.size(), bytes);
  return 0;
}

// libFuzzer's byte mutator, which the targets' custom mutators fall back to.
// Replay never mutates; this only satisfies the linker.
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t*, std::size_t size, std::size_t) { return size; }
