// command_text.cpp — see command_text.h.
#include "command_text.h"

#include <type_traits>

#include "command_fields.h"
#include "number_text.h"

namespace vgc {
namespace {

// ---- printing ------------------------------------------------------------

template <class T> void print_scalar(std::string& out, const T& v, FieldHint hint) {
  out += ' ';
  if constexpr (std::is_same_v<T, double>) {
    out += format_f64(v);
  } else if constexpr (std::is_same_v<T, float>) {
    out += format_f32(v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    out += format_quoted(v);
  } else {
    static_assert(std::is_integral_v<T>);
    if (hint == FieldHint::LayerType && is_layer_type(static_cast<std::uint8_t>(v))) {
      out += layer_type_name(static_cast<std::uint8_t>(v));
    } else if (hint == FieldHint::RealFormat && v <= 1) {
      out += v == 0 ? "REAL32" : "REAL64";
    } else {
      out += format_uint(static_cast<std::uint32_t>(v), static_cast<int>(sizeof(T) * 8));
    }
  }
}

struct Printer {
  std::string& out;
  template <class T> void operator()(const char*, const T& v, FieldHint hint) {
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      for (const auto& e : v) print_scalar(out, e, hint);
    } else {
      print_scalar(out, v, hint);
    }
  }
};

// ---- parsing -------------------------------------------------------------

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

class LineReader {
 public:
  LineReader(std::string_view line, std::size_t number) : line_(line), number_(number) {}

  void skip_blanks() {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
  }
  bool at_end() {
    skip_blanks();
    return pos_ >= line_.size() || line_[pos_] == '#';
  }
  std::size_t column() const { return pos_ + 1; }
  // Next bare token (up to a blank or a comment).
  std::string_view token() {
    skip_blanks();
    const std::size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_]) && line_[pos_] != '#') ++pos_;
    return line_.substr(start, pos_ - start);
  }
  std::string_view rest() const { return line_.substr(pos_); }
  void advance(std::size_t n) { pos_ += n; }
  void fail(std::size_t column, std::string message, TextError* e) const {
    e->line = number_;
    e->column = column;
    e->message = std::move(message);
  }

 private:
  std::string_view line_;
  std::size_t number_;
  std::size_t pos_ = 0;
};

std::string shown(std::string_view tok) {
  if (tok.empty()) return "end of line";
  std::string s = "\"";
  for (char c : tok.substr(0, 40)) s += c;
  if (tok.size() > 40) s += "...";
  return s + "\"";
}

template <class T> const char* type_word(FieldHint hint) {
  if (hint == FieldHint::LayerType) return "layer type (VERTEX_XYZ ... POLYGON_FACE_REAL or 0..255)";
  if (hint == FieldHint::RealFormat) return "real format (REAL32, REAL64 or 0..255)";
  if constexpr (std::is_same_v<T, double>) return "real64";
  if constexpr (std::is_same_v<T, float>) return "real32";
  if constexpr (std::is_same_v<T, std::string>) return "quoted name";
  if constexpr (sizeof(T) == 1) return "uint8";
  if constexpr (sizeof(T) == 2) return "uint16";
  return "uint32";
}

struct Parser {
  LineReader& in;
  TextError* error;
  bool ok = true;

  template <class T> bool scalar(const char* name, T& v, FieldHint hint) {
    in.skip_blanks();
    const std::size_t col = in.column();
    const auto expected = [&](std::string_view found) {
      in.fail(col, std::string("expected ") + name + " (" + type_word<T>(hint) + "), found " + shown(found),
              error);
      return false;
    };
    if constexpr (std::is_same_v<T, std::string>) {
      std::size_t used = 0, bad = 0;
      if (in.rest().empty() || in.rest()[0] != '"') return expected(in.token());
      if (!parse_quoted(in.rest(), &v, &used, &bad)) {
        in.fail(col + bad, std::string("bad quoted ") + name +
                               ": use \\\" \\\\ or \\xHH escapes and close the quote on the same line",
                error);
        return false;
      }
      in.advance(used);
      // Fields are separated by blanks: `"a"5` is not two fields.
      if (!in.rest().empty() && !is_blank(in.rest()[0]) && in.rest()[0] != '#') {
        const std::size_t after = in.column();
        in.fail(after, std::string("expected a blank after the closing quote of ") + name + ", found " +
                           shown(in.token()),
                error);
        return false;
      }
      return true;
    } else {
      const std::string_view tok = in.token();
      if constexpr (std::is_same_v<T, double>) {
        if (!parse_f64(tok, &v)) return expected(tok);
      } else if constexpr (std::is_same_v<T, float>) {
        if (!parse_f32(tok, &v)) return expected(tok);
      } else {
        std::uint32_t u = 0;
        std::uint8_t named = 0;
        if (hint == FieldHint::LayerType && parse_layer_type_name(tok, &named)) {
          u = named;
        } else if (hint == FieldHint::RealFormat && (tok == "REAL32" || tok == "REAL64")) {
          u = tok == "REAL64";
        } else if (!parse_uint(tok, static_cast<int>(sizeof(T) * 8), &u)) {
          return expected(tok);
        }
        v = static_cast<T>(u);
      }
      return true;
    }
  }

  template <class T> void operator()(const char* name, T& v, FieldHint hint) {
    if (!ok) return;
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      for (std::size_t i = 0; i < v.size() && ok; ++i) {
        const std::string element = std::string(name) + "[" + std::to_string(i) + "]";
        ok = scalar(element.c_str(), v[i], hint);
      }
    } else {
      ok = scalar(name, v, hint);
    }
  }
};

template <std::size_t I = 0> bool make_by_verb(std::string_view verb, Command* out) {
  if constexpr (I < kCommandKinds) {
    if (command_verb(I) == verb) {
      out->emplace<I>();
      return true;
    }
    return make_by_verb<I + 1>(verb, out);
  } else {
    return false;
  }
}

}  // namespace

std::string TextError::to_string() const {
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + message;
}

std::string print_command(const Command& c) {
  std::string out(command_verb(c));
  std::visit([&](const auto& x) { visit_fields_const(x, Printer{out}); }, c);
  return out;
}

std::string print_commands(const std::vector<Command>& cs) {
  std::string out;
  for (const auto& c : cs) {
    out += print_command(c);
    out += '\n';
  }
  return out;
}

bool parse_command_line(std::string_view line, std::size_t line_number, Command* out,
                        bool* blank, TextError* error) {
  LineReader in(line, line_number);
  *blank = in.at_end();
  if (*blank) return false;
  const std::size_t verb_col = in.column();
  const std::string_view verb = in.token();
  if (!make_by_verb(verb, out)) {
    in.fail(verb_col, "expected a command verb (layer_create, vertex_set_xyz_real64, ...), found " + shown(verb),
            error);
    return false;
  }
  Parser p{in, error};
  std::visit([&](auto& x) { visit_fields(x, p); }, *out);
  if (!p.ok) return false;
  if (!in.at_end()) {
    const std::size_t col = in.column();
    in.fail(col, "expected end of line after " + std::string(verb) + ", found " + shown(in.token()), error);
    return false;
  }
  return true;
}

bool parse_commands(std::string_view text, std::vector<Command>* out, TextError* error,
                    std::vector<std::size_t>* lines) {
  std::size_t line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    Command c;
    bool blank = false;
    if (parse_command_line(line, line_number, &c, &blank, error)) {
      out->push_back(std::move(c));
      if (lines) lines->push_back(line_number);
    } else if (!blank) {
      return false;
    }
  }
  return true;
}

}  // namespace vgc
