// vgc_main.cpp — the vgc command line: certify, apply, serve, replay, fuzz, ...
// Each subcommand lives in its own cmd_*.cpp; this file only wires them up.
#include <CLI/CLI.hpp>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"vgc: the Verse geometry conformance and fuzz suite"};
  app.require_subcommand(1);
  int exit_code = 0;
  vgc::cli::add_apply(app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;  // usage errors are exit code 2
  }
  return exit_code;
}
