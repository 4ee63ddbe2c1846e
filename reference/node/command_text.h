// command_text.h — the text form of commands: one command per line.
//
// Spec: docs/spec_facts.md (command set); docs/commands.md (grammar).
//
//   # a comment runs to the end of the line
//   layer_create 2 "uv" VERTEX_REAL 0 0.5
//   vertex_set_xyz_real64 0 0 -1 1 -1
//
// A line is a verb followed by its fields in wire order, separated by spaces
// or tabs; arrays (corners, position, rotation) are spelled out as their
// elements. Numbers and names use the exact forms of number_text.h, so
// parse(print(c)) is bit-identical to c. Parsing never throws and never
// crashes: bad input gives a TextError naming line, column and expectation.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "command.h"

namespace vgc {

struct TextError {
  std::size_t line = 0;    // 1-based
  std::size_t column = 0;  // 1-based, in bytes
  std::string message;     // "expected vertex_id (uint32), found \"x\""
  std::string to_string() const;  // "line 3, column 24: expected ..."
};

// One command in its canonical text form, without a newline.
std::string print_command(const Command& c);
// Commands one per line, each ending in '\n'.
std::string print_commands(const std::vector<Command>& cs);

// Parses one line (comments and surrounding blanks allowed). Returns false
// with *error set (line = `line_number`) when the line is not a command;
// *is_blank is set for a line holding nothing but blanks or a comment.
bool parse_command_line(std::string_view line, std::size_t line_number, Command* out,
                        bool* is_blank, TextError* error);

// A whole file. On the first error returns false, *error says where, and
// *out holds the commands of the lines before it. When `lines` is given it
// receives each command's 1-based line number.
bool parse_commands(std::string_view text, std::vector<Command>* out, TextError* error,
                    std::vector<std::size_t>* lines = nullptr);

}  // namespace vgc
