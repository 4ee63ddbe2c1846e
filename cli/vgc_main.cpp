// vgc_main.cpp — the vgc command line. Each subcommand lives in its own
// cmd_*.cpp and registers itself (subcommand.h); this file only runs them.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "option_values.h"
#include "program_command.h"
#include "subcommand.h"
#include "terminal_text.h"
#include "version.h"

namespace vgc::cli {
namespace {
std::vector<AddSubcommand>& registry() {
  static std::vector<AddSubcommand> r;
  return r;
}
}  // namespace

Subcommand::Subcommand(AddSubcommand add) { registry().push_back(add); }

void add_all_subcommands(CLI::App& app, int* exit_code) {
  for (AddSubcommand add : registry()) add(app, exit_code);
}

}  // namespace vgc::cli

int main(int argc, char** argv) {
  CLI::App app{"vgc: the Verse geometry conformance and fuzz suite"};
  app.require_subcommand(1);
  // --version: the program, the clause catalog and the report format (version.h).
  app.set_version_flag("--version", fmt::format("vgc {}\nclause catalog version {}\nreport format version {}",
                                                vgc::kVgcVersion, vgc::kClauseCatalogVersion,
                                                vgc::kReportFormatVersion));
  // Printed replay and re-run lines name this program as a shell can run it
  // where it is installed (program_command.h).
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const char* path = std::getenv("PATH");
  if (!ec) vgc::set_program_command(vgc::program_command_for(self.string(), path ? path : ""));
  int exit_code = 0;
  vgc::cli::add_all_subcommands(app, &exit_code);
  vgc::cli::refuse_empty_values(app);  // `--reports ""`: exit 2 naming the option (option_values.h)
  // A word where the subcommand goes that names none: say which there are.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || sub->get_name() == argv[1];
    }
    if (!known) {
      vgc::cli::say(stderr, "vgc: unknown command '{}': use one of {} (vgc --help says what each does)\n", argv[1],
                 names);
      return 2;
    }
  }
  // Usage errors name the subcommand whose --help lists the options and
  // the values they take.
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    std::string where = "vgc";
    for (const CLI::App* sub : a->get_subcommands()) where += " " + sub->get_name();
    return where + ": " + e.what() + "\nRun `" + where + " --help` for the options and the values they take.\n";
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;  // usage errors are exit code 2
  }
  return exit_code;
}
