// subcommand.h — how a cmd_*.cpp file adds its subcommand to `vgc`.
//
// Each cmd_*.cpp defines one static Subcommand object; vgc_main.cpp adds
// every registered one to the CLI11 app. Adding a subcommand is adding a
// file: no list to edit.
#pragma once

#include <CLI/CLI.hpp>

namespace vgc::cli {

// `add` declares the subcommand on `app`; its callback stores the process
// exit code in *exit_code (0 success, 1 a negative verdict, 2 usage or
// infrastructure error).
using AddSubcommand = void (*)(CLI::App& app, int* exit_code);

struct Subcommand {
  explicit Subcommand(AddSubcommand add);
};

void add_all_subcommands(CLI::App& app, int* exit_code);

}  // namespace vgc::cli
