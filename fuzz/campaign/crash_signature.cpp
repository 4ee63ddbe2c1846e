// crash_signature.cpp — see crash_signature.h.
#include "crash_signature.h"

#include <regex>
#include <sstream>

#include "clause.h"

namespace vgc::fuzz {
namespace {

const std::regex& clause_re() {
  static const std::regex clause(R"(\b[A-Z][A-Z0-9]*(-[A-Z0-9]+)*-[0-9]+\b)");
  return clause;
}

}  // namespace

// Digits folded to N, except inside clause ids (BONE-FOREST-1), which stay
// exact: "bones.stateful: BONE-FOREST-1 (MUST, fail): bone 3" becomes
// "bones.stateful: BONE-FOREST-1 (MUST, fail): bone N".
std::string fold_digits_keep_clauses(const std::string& s) {
  static const std::regex digits(R"(\d+)");
  std::string out;
  auto from = s.cbegin();
  for (std::sregex_iterator it(s.begin(), s.end(), clause_re()), end; it != end; ++it) {
    out += std::regex_replace(std::string(from, (*it)[0].first), digits, "N");
    out += it->str();
    from = (*it)[0].second;
  }
  return out + std::regex_replace(std::string(from, s.cend()), digits, "N");
}

// The fuzz target's own FINDING line (data in quotes dropped), else the
// sanitizer's error kind and first frame of ours, else the first UBSan
// "runtime error", else "unknown".
CrashSignature crash_signature(const std::string& output) {
  std::istringstream in(output);
  std::string line, kind;
  static const std::regex digits(R"(\d+)");
  while (std::getline(in, line)) {
    if (auto at = line.find("vgc-fuzz: FINDING in "); at != std::string::npos) {
      std::string s = line.substr(at + 10);
      s = s.substr(0, s.find('"'));
      // A finding named by its clause is grouped by the target, the clause
      // and its status ("CLAUSE (LEVEL, status)"), not by the message: one
      // bug shown with other values or commands is one finding.
      static const std::regex named(R"(^(.*?: [A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+ \([A-Z-]+, [a-z-]+\)): )");
      std::smatch m;
      if (std::regex_search(s, m, named)) return {std::regex_replace(m[1].str(), digits, "N"), fold_digits_keep_clauses(s)};
      return {std::regex_replace(s, digits, "N"), fold_digits_keep_clauses(s)};
    }
    if (auto at = line.find("runtime error: "); at != std::string::npos) {
      const std::string u =
          "ubsan: " + std::regex_replace(line.substr(0, at), std::regex(R"(^.*/)"), "") + line.substr(at + 15);
      return {u, u};
    }
    if (auto at = line.find("ERROR: AddressSanitizer: "); at != std::string::npos && kind.empty()) {
      kind = line.substr(at + 25);
      kind = kind.substr(0, kind.find(' '));
    }
    if (auto at = line.find("ERROR: libFuzzer: "); at != std::string::npos && kind.empty())
      kind = line.substr(at + 18);
    if (!kind.empty()) {
      std::smatch m;
      static const std::regex frame(R"(#\d+ 0x[0-9a-f]+ in (\S+))");
      if (std::regex_search(line, m, frame)) {
        const std::string f = m[1];
        if (f.find("__sanitizer") == std::string::npos && f.find("fuzzer::") == std::string::npos &&
            f.find("__asan") == std::string::npos && f.find("__ubsan") == std::string::npos &&
            f != "abort" && f != "raise" && f != "__GI_abort" && f != "__GI_raise" &&
            f.find("pthread_kill") == std::string::npos && f.find("libc.so") == std::string::npos)
          return {kind + " in " + f, kind + " in " + f};
      }
    }
  }
  const std::string k = kind.empty() ? "unknown" : kind;
  return {k, k};
}

std::string status_of_finding(const std::string& line) {
  static const std::regex form(R"(-[0-9]+ \([A-Z-]+, ([a-z-]+)\): )");
  std::smatch m;
  return std::regex_search(line, m, form) ? m[1].str() : std::string{};
}

std::string clause_of_finding(const std::string& line) {
  // "CLAUSE (LEVEL, status): " — the form of clause_finding.h.
  static const std::regex form(R"((?:^|: )([A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+) \([A-Z-]+, [a-z]+\): )");
  std::smatch m;
  if (!std::regex_search(line, m, form)) return {};
  return find_clause(m[1].str()) ? m[1].str() : std::string{};
}

}  // namespace vgc::fuzz
