// symbolize_functions.cpp — see symbolize_functions.h.
#include "symbolize_functions.h"

#include <elf.h>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "exec_implementation.h"  // shell_quote
#include "reaped_command.h"

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;

// The lowest address a module's file is loaded at (p_vaddr - p_offset of
// its PT_LOAD segments): what an offset from the load address is added to.
std::optional<std::uint64_t> lowest_load_address(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  Elf64_Ehdr eh{};
  if (!f.read(reinterpret_cast<char*>(&eh), sizeof eh) || std::string_view(reinterpret_cast<char*>(eh.e_ident), 4) != ELFMAG ||
      eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_phentsize != sizeof(Elf64_Phdr) || eh.e_phnum == 0 ||
      eh.e_phnum > 4096)
    return std::nullopt;
  std::optional<std::uint64_t> lowest;
  for (unsigned i = 0; i < eh.e_phnum; ++i) {
    Elf64_Phdr ph{};
    f.seekg(static_cast<std::streamoff>(eh.e_phoff + i * sizeof ph));
    if (!f.read(reinterpret_cast<char*>(&ph), sizeof ph)) return std::nullopt;
    if (ph.p_type != PT_LOAD || ph.p_vaddr < ph.p_offset) continue;
    const std::uint64_t a = ph.p_vaddr - ph.p_offset;
    if (!lowest || a < *lowest) lowest = a;
  }
  return lowest;
}

// llvm-symbolizer on PATH (or its versioned name), "" when there is none.
std::string find_symbolizer() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    for (const char* name : {"llvm-symbolizer", "llvm-symbolizer-16", "llvm-symbolizer-15", "llvm-symbolizer-14"}) {
      const fs::path p = fs::path(dir.empty() ? "." : dir) / name;
      if (access(p.c_str(), X_OK) == 0) return p.string();
    }
  return {};
}

std::string hex_name(const std::string& module, std::uint32_t offset) {
  return fmt::format("{}+0x{:x}", fs::path(module).filename().string(), offset);
}

// Names `addresses` of `module` with llvm-symbolizer: (function, file:line)
// per address, in order; empty when it could not be run.
std::vector<std::pair<std::string, std::string>> run_symbolizer(const std::string& symbolizer,
                                                                const std::string& module,
                                                                const std::vector<std::uint64_t>& addresses) {
  char input[] = "/tmp/vgc-symbolize-XXXXXX";
  const int fd = mkstemp(input);
  if (fd < 0) return {};
  close(fd);
  {
    std::ofstream in(input);
    for (std::uint64_t a : addresses) in << fmt::format("0x{:x}\n", a);
  }
  const std::string command = shell_quote(symbolizer) + " --obj=" + shell_quote(module) +
                              " --functions=linkage --demangle --no-inlines < " +
                              shell_quote(input) + " 2>/dev/null";
  std::vector<std::pair<std::string, std::string>> out;
  if (std::string text; run_reaped_shell(command, &text, std::size_t{64} << 20) != -1) {
    // One block per address: the function's name, its file:line:column,
    // then an empty line.
    std::istringstream lines(text);
    std::string name, where, blank;
    while (out.size() < addresses.size() && std::getline(lines, name) && std::getline(lines, where)) {
      std::getline(lines, blank);
      if (const auto c = where.rfind(':'); c != std::string::npos && where.find(':') != c) where.resize(c);
      if (where.rfind("??", 0) == 0) where.clear();
      else if (const auto c = where.rfind(':'); c != std::string::npos)
        where = fs::path(where.substr(0, c)).lexically_normal().string() + where.substr(c);
      out.emplace_back(name == "??" ? std::string() : name, where);
    }
  }
  std::remove(input);
  if (out.size() != addresses.size()) out.clear();
  return out;
}

}  // namespace

bool place_before(const NamedFunction& a, const NamedFunction& b) {
  // file, then line as a number, then name
  auto split = [](const std::string& where) {
    const auto c = where.rfind(':');
    unsigned long line = 0;
    if (c != std::string::npos) std::from_chars(where.data() + c + 1, where.data() + where.size(), line);
    return std::pair{c == std::string::npos ? where : where.substr(0, c), line};
  };
  const auto pa = split(a.location), pb = split(b.location);
  return std::tie(pa.first, pa.second, a.name) < std::tie(pb.first, pb.second, b.name);
}

std::vector<NamedFunction> symbolize_functions(const std::vector<ImplementationFunction>& functions,
                                               std::string* note) {
  std::vector<NamedFunction> named(functions.size());
  std::map<std::string, std::vector<std::size_t>> by_module;
  for (std::size_t i = 0; i < functions.size(); ++i) {
    named[i].name = hex_name(functions[i].module, functions[i].offset);
    named[i].entered = functions[i].entered;
    by_module[functions[i].module].push_back(i);
  }
  std::vector<std::string> problems;
  const std::string symbolizer = find_symbolizer();
  if (symbolizer.empty() && !functions.empty())
    problems.push_back("no llvm-symbolizer on PATH (Debian: llvm): functions are named by module and offset");
  for (const auto& [module, which] : by_module) {
    if (symbolizer.empty()) break;
    const auto base = lowest_load_address(module);
    if (!base) {
      problems.push_back(fmt::format("{}: not a readable 64-bit ELF file: its {} functions are named by offset",
                                     module, which.size()));
      continue;
    }
    std::vector<std::uint64_t> addresses;
    for (std::size_t i : which) addresses.push_back(*base + functions[i].offset);
    const auto names = run_symbolizer(symbolizer, module, addresses);
    if (names.empty()) {
      problems.push_back(fmt::format("{}: llvm-symbolizer named nothing: its functions are named by offset", module));
      continue;
    }
    std::size_t unnamed = 0;
    for (std::size_t k = 0; k < which.size(); ++k) {
      if (names[k].first.empty()) {
        ++unnamed;
        continue;
      }
      named[which[k]].name = names[k].first;
      named[which[k]].location = names[k].second;
    }
    if (unnamed)
      problems.push_back(fmt::format("{}: {} functions have no symbol (built without -g, or stripped)", module,
                                     unnamed));
  }
  *note = "";
  for (const std::string& p : problems) *note += (note->empty() ? "" : "; ") + p;
  return named;
}

std::string format_function_report(const std::vector<NamedFunction>& named, const std::string& note) {
  std::vector<const NamedFunction*> never, entered;
  for (const NamedFunction& f : named) (f.entered ? entered : never).push_back(&f);
  auto by_place = [](const NamedFunction* a, const NamedFunction* b) { return place_before(*a, *b); };
  std::sort(never.begin(), never.end(), by_place);
  std::sort(entered.begin(), entered.end(), by_place);
  std::string md = "# The implementation's functions\n\n";
  md += fmt::format("{} of {} functions were entered by some input of this campaign; {} never were.\n",
                    entered.size(), named.size(), never.size());
  if (!note.empty()) md += "\nNot every function could be named: " + note + ".\n";
  auto list = [&](const char* title, const std::vector<const NamedFunction*>& fs) {
    md += fmt::format("\n## {} ({})\n\n", title, fs.size());
    for (const NamedFunction* f : fs)
      md += "- `" + f->name + "`" + (f->location.empty() ? "" : " — " + f->location) + "\n";
  };
  list("Never entered", never);
  list("Entered", entered);
  return md;
}

}  // namespace vgc::fuzz
