// read_file.h — a whole file (or standard input) into a string, for the
// subcommands that read command files and fuzz inputs.
//
// Spec: none (command-line plumbing).
//
// Rationale: apply, replay and fuzz each had their own copy; bytes are read
// unchanged (binary mode), so CRLF files and binary fuzz inputs survive.
#pragma once

#include <filesystem>
#include <string>

namespace vgc::cli {

// Reads the whole of `path` into *out. Returns false (leaving *out
// unspecified) when it cannot be opened. Never throws.
bool read_file(const std::filesystem::path& path, std::string* out);

// Why `path` cannot be read, for an error message: "no such file", "it is
// a directory", or the system's reason. Never throws.
std::string read_failure(const std::filesystem::path& path);

// Reads standard input to its end into *out. Never throws.
void read_stdin(std::string* out);

}  // namespace vgc::cli
