// cmd_apply.cpp — `vgc apply FILE [--derived]`: run a command file on a fresh
// reference node; print per command whether it applied or why it was
// rejected, then the snapshot.
//
// Exit codes: 0 the file was read and run (rejections are results, not
// errors); 1 with --strict when any command was rejected; 2 when the file
// cannot be read or does not parse (the error names line and column).
#include <fmt/core.h>

#include <memory>

#include "command_text.h"
#include "derived_document.h"
#include "node.h"
#include "read_file.h"
#include "snapshot.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

struct ApplyOptions {
  std::string file;
  bool derived = false;
  bool strict = false;
};

int run_apply(const ApplyOptions& o) {
  std::string text;
  if (o.file == "-") {
    read_stdin(&text);
  } else if (!read_file(o.file, &text)) {
    say(stderr,
               "vgc apply: cannot read {} ({}): give the path of a command file (docs/commands.md), or - for "
               "standard input\n",
               o.file, read_failure(o.file));
    return 2;
  }
  std::vector<Command> commands;
  std::vector<std::size_t> lines;
  TextError error;
  if (!parse_commands(text, &commands, &error, &lines)) {
    say(stderr, "{}:{}:{}: error: {}\n", o.file, error.line, error.column, error.message);
    return 2;
  }
  Node node;
  std::size_t rejected = 0;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const Reason r = node.apply(commands[i]);
    if (r == Reason::Ok) {
      say("{:>5}: ok                   {}\n", lines[i], print_command(commands[i]));
    } else {
      ++rejected;
      say("{:>5}: rejected {:<19} {}\n", lines[i], reason_name(r), print_command(commands[i]));
    }
  }
  say("# {} commands, {} applied, {} rejected\n", commands.size(), commands.size() - rejected,
             rejected);
  say("{}", print_snapshot(node));
  if (o.derived) say("{}", print_derived(node));
  return o.strict && rejected > 0 ? 1 : 0;
}

void add_apply(CLI::App& app, int* exit_code) {
  auto opts = std::make_shared<ApplyOptions>();
  CLI::App* sub = app.add_subcommand("apply", "Run a command file on a fresh reference node and print the result");
  sub->add_option("file", opts->file, "Command file (text form; - for standard input)")->required();
  sub->add_flag("--derived", opts->derived, "Also print effective creases and bone poses");
  sub->add_flag("--strict", opts->strict, "Exit 1 when any command is rejected");
  sub->callback([opts, exit_code] { *exit_code = run_apply(*opts); });
}

const Subcommand kApply{add_apply};

}  // namespace

}  // namespace vgc::cli
