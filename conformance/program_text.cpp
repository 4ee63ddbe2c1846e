// program_text.cpp — see program_text.h.
#include "program_text.h"

#include <charconv>
#include <algorithm>
#include <iterator>

namespace vgc {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

// The blank-separated tokens of `line` from byte `from` on, with their
// 1-based columns.
std::vector<std::pair<std::string, std::size_t>> tokens(std::string_view line, std::size_t from) {
  std::vector<std::pair<std::string, std::size_t>> out;
  std::size_t i = from;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    out.emplace_back(std::string(line.substr(start, i - start)), start + 1);
  }
  return out;
}

void set_error(TextError* error, std::size_t line, std::size_t column, std::string message) {
  error->line = line;
  error->column = column;
  error->message = std::move(message);
}

}  // namespace

std::string print_capability_directive(const CapabilityRequest& request) {
  std::string out = "#! capability " + request.capability + " variant " + std::to_string(request.variant);
  if (request.draw) out += " draw " + std::to_string(*request.draw);
  return out + "\n";
}

std::string print_program(const Program& program) {
  std::string out = print_commands(program.commands);
  if (program.history_kind) out += std::string("#! history ") + finding_kind_name(*program.history_kind) + "\n";
  if (program.mesh) out += "#! mesh\n";
  if (program.request) out += print_capability_directive(*program.request);
  return out;
}

namespace {

// A one-per-file directive after the last command: false with *error set
// when it is the second one (`seen`) or comes before a command.
bool placed_once(const char* name, bool seen, std::size_t line_number, std::size_t last_command, TextError* error) {
  if (seen) {
    set_error(error, line_number, 1, std::string("a second ") + name + " directive");
    return false;
  }
  if (line_number < last_command) {
    set_error(error, line_number, 1,
              std::string("the ") + name + " directive must follow the last command (line " +
                  std::to_string(last_command) + ")");
    return false;
  }
  return true;
}

// "#! history KIND": the program reproduces a finding that depends on the
// implementation's history. Returns false with *error set on a malformed one.
bool parse_history_directive(const std::vector<std::pair<std::string, std::size_t>>& t, std::string_view line,
                             std::size_t line_number, std::size_t last_command, Program* out, TextError* error) {
  if (!placed_once("history", out->history_kind.has_value(), line_number, last_command, error)) return false;
  // Hidden state is no kind a history is confirmed for (confirm_finding.h is_call_failure and wrong answers).
  const std::optional<FindingKind> kind = t.size() == 2 ? finding_kind_named(t[1].first) : std::nullopt;
  if (!kind || *kind == FindingKind::HiddenState) {
    set_error(error, line_number, t.size() < 2 ? line.size() + 1 : t[1].second,
              "expected \"#! history KIND\" with KIND one of crash, timeout, protocol-error, wrong-answer");
    return false;
  }
  out->history_kind = kind;
  return true;
}

// "#! mesh": the program is a user's mesh as `vgc certify --mesh` judged it.
bool parse_mesh_directive(const std::vector<std::pair<std::string, std::size_t>>& t, std::size_t line_number,
                          std::size_t last_command, Program* out, TextError* error) {
  if (!placed_once("mesh", out->mesh, line_number, last_command, error)) return false;
  if (t.size() != 1) {
    set_error(error, line_number, t[1].second, "expected \"#! mesh\" alone on its line");
    return false;
  }
  out->mesh = true;
  return true;
}

}  // namespace

bool parse_program(std::string_view text, Program* out, TextError* error, std::vector<std::size_t>* lines,
                   std::size_t* directive_line) {
  out->commands.clear();
  out->request.reset();
  out->history_kind.reset();
  out->mesh = false;
  if (directive_line) *directive_line = 0;
  std::vector<std::size_t> command_lines;
  if (!parse_commands(text, &out->commands, error, &command_lines)) {
    if (lines) *lines = command_lines;
    return false;
  }
  if (lines) *lines = command_lines;
  const std::size_t last_command = command_lines.empty() ? 0 : command_lines.back();

  std::size_t line_number = 0, found = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    if (line.substr(0, 2) != "#!") continue;
    const auto t = tokens(line, 2);
    if (!t.empty() && t[0].first == "history") {
      if (!parse_history_directive(t, line, line_number, last_command, out, error)) return false;
      continue;
    }
    if (!t.empty() && t[0].first == "mesh") {
      if (!parse_mesh_directive(t, line_number, last_command, out, error)) return false;
      continue;
    }
    if (t.empty() || t[0].first != "capability") continue;  // an ordinary comment
    if (found) {
      set_error(error, line_number, 1,
                "a second capability directive (the first is on line " + std::to_string(found) + ")");
      return false;
    }
    if (line_number < last_command) {
      set_error(error, line_number, 1,
                "the capability directive must follow the last command (line " + std::to_string(last_command) + ")");
      return false;
    }
    const std::size_t end_column = line.size() + 1;
    if (t.size() < 2) {
      set_error(error, line_number, end_column, "expected a capability name after \"capability\"");
      return false;
    }
    for (char c : t[1].first)
      if (!is_name_char(c)) {
        set_error(error, line_number, t[1].second, "expected a capability name (letters, digits, - and _), found \"" +
                                                       t[1].first + "\"");
        return false;
      }
    if (t.size() < 3 || t[2].first != "variant") {
      set_error(error, line_number, t.size() < 3 ? end_column : t[2].second,
                "expected \"variant\" after the capability name");
      return false;
    }
    if (t.size() < 4) {
      set_error(error, line_number, end_column, "expected the variant number");
      return false;
    }
    const std::string& n = t[3].first;
    int variant = 0;
    const auto [n_end, n_ec] = std::from_chars(n.data(), n.data() + n.size(), variant);
    if (n.empty() || n.size() > 9 || n[0] == '-' || n_ec != std::errc() || n_end != n.data() + n.size()) {
      set_error(error, line_number, t[3].second, "expected the variant number (1 to 9 digits), found \"" + n + "\"");
      return false;
    }
    std::optional<std::uint32_t> draw;
    std::size_t next = 4;
    if (t.size() > next && t[next].first == "draw") {
      if (t.size() < next + 2) {
        set_error(error, line_number, end_column, "expected the drawn number after \"draw\"");
        return false;
      }
      const std::string& d = t[next + 1].first;
      std::uint32_t drawn = 0;
      const auto [d_end, d_ec] = std::from_chars(d.data(), d.data() + d.size(), drawn);
      const bool ok = !d.empty() && d_ec == std::errc() && d_end == d.data() + d.size();
      if (!ok) {
        set_error(error, line_number, t[next + 1].second,
                  "expected the drawn number (0 to 4294967295), found \"" + d + "\"");
        return false;
      }
      draw = drawn;
      next += 2;
    }
    if (t.size() > next) {
      set_error(error, line_number, t[next].second,
                "unexpected \"" + t[next].first + "\" after the " + (next == 4 ? "variant" : "drawn") + " number");
      return false;
    }
    out->request = CapabilityRequest{t[1].first, variant, draw};
    found = line_number;
  }
  if (directive_line) *directive_line = found;
  return true;
}

}  // namespace vgc
