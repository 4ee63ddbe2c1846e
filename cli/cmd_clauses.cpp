// cmd_clauses.cpp — `vgc clauses [--markdown] [--clauses GLOB]`: the clause
// catalog (conformance/catalog_markdown.h renders it).
#include <fmt/core.h>

#include <memory>

#include "catalog_markdown.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

struct Options {
  bool markdown = false;
  std::string glob = "*";
};

int run(const Options& o) {
  fmt::print("{}", o.markdown ? clause_catalog_markdown(o.glob) : clause_catalog_list(o.glob));
  return 0;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("clauses", "List the clause catalog: id, level, group, checking properties");
  sub->add_flag("--markdown", o->markdown, "Print the full catalog as Markdown (docs/clauses.md)");
  sub->add_option("--clauses", o->glob, "Only clauses matching these comma-separated glob patterns");
  sub->callback([o, exit_code] { *exit_code = run(*o); });
}

const Subcommand kClauses{add};

}  // namespace
}  // namespace vgc::cli
