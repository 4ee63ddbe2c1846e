// commands.h — the subcommands of the vgc command line, one file each.
#pragma once

#include <CLI/CLI.hpp>

namespace vgc::cli {

// `vgc apply FILE`: runs a command file on a fresh reference node.
void add_apply(CLI::App& app, int* exit_code);

}  // namespace vgc::cli
