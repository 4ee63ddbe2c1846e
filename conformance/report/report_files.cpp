// report_files.cpp — run directory naming, counterexample files, and the
// whole-or-nothing write of a report (report.h).
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

#include "command_text.h"
#include "display_text.h"
#include "exec_implementation.h"  // shell_quote
#include "finding_picture.h"
#include "obj_writer.h"
#include "program_command.h"
#include "program_text.h"
#include "report.h"

namespace vgc {
namespace fs = std::filesystem;

namespace {

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '_' || c == '-';
    out += ok ? c : '-';
    if (out.size() >= 60) break;
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.empty() ? "implementation" : out;
}

bool write_file(const fs::path& path, const std::string& text, std::string* error) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    *error = "cannot write " + path.string();
    return false;
  }
  return true;
}

}  // namespace

std::string default_run_dir(const std::string& reports_root, const RunResult& run, const ReportContext& ctx) {
  std::string stamp;
  for (char c : ctx.started)
    if (c != ':' && c != '-') stamp += c;
  std::string name = stamp + "-seed" + std::to_string(run.options.seed);
  if (run.options.shard_count > 1)
    name += "-shard" + std::to_string(run.options.shard_index + 1) + "of" + std::to_string(run.options.shard_count);
  return (fs::path(reports_root) / slug(ctx.implementation_spec) / name).string();
}

bool claim_run_dir(const std::string& reports_root, const RunResult& run, ReportContext* ctx, std::string* error) {
  const fs::path base(default_run_dir(reports_root, run, *ctx));
  std::error_code ec;
  fs::path dir = base;
  // A parent can vanish between its creation and our mkdir: a run checking
  // the same --reports at once (cmd_certify's reports_writable) removes the
  // empty directories it created for its check. Then again, a few times.
  for (int attempt = 0; attempt < 10; ++attempt) {
    ec.clear();
    fs::create_directories(base.parent_path(), ec);
    dir = base;
    // One mkdir claims a name: a run started in the same second with the same
    // seed (a CI matrix, a script) gets -2, -3, ... instead of sharing it.
    for (int k = 2; !ec && !fs::create_directory(dir, ec) && !ec && k < 10000; ++k)
      dir = base.string() + "-" + std::to_string(k);
    if (ec != std::errc::no_such_file_or_directory) break;
  }
  if (ec || !fs::is_empty(dir, ec)) {
    *error = "cannot create a run directory under " + base.parent_path().string() + ": " +
             (ec ? ec.message() : std::string("every name is taken"));
    return false;
  }
  ctx->run_dir = dir.string();
  return true;
}

std::string counterexample_path(const ClauseOutcome& co) {
  return "counterexamples/" + std::string(co.clause->id) + (co.part > 0 ? "." + std::to_string(co.part + 1) : "") +
         ".vgc";
}

std::string inline_program(const ClauseOutcome& co) {
  const std::size_t n = co.program.commands.size();
  if (n <= kInlineCommands) return print_program(co.program);
  Program head, tail;
  head.commands.assign(co.program.commands.begin(), co.program.commands.begin() + 20);
  tail.commands.assign(co.program.commands.end() - 20, co.program.commands.end());
  tail.request = co.program.request;
  return print_program(head) + "# ... " + std::to_string(n - 40) + " more commands (" + std::to_string(n) +
         " in all: " + counterexample_path(co) + " holds every one) ...\n" + print_program(tail);
}

std::string commands_counted(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " command" : " commands");
}

std::string counterexample_heading(const ClauseOutcome& co) {
  if (!co.program_origin.empty()) return co.program_origin;
  return co.tolerated_from_start ? "First program it was seen on (tolerated from the start, not shrunk)"
                                 : "Shrunk counterexample";
}

std::string vgc_environment_prefix() {
  std::vector<std::string> vars;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    const auto eq = entry.find('=');
    if (entry.rfind("VGC_", 0) != 0 || eq == std::string::npos) continue;
    vars.push_back(entry.substr(0, eq) + "=" + shell_quote(entry.substr(eq + 1)) + " ");
  }
  std::sort(vars.begin(), vars.end());
  std::string out;
  for (const auto& v : vars) out += v;
  return out;
}

// The file by its absolute path: a replay line works from any directory.
std::string absolute_file(const std::string& file) {
  std::error_code ec;
  const fs::path p = fs::absolute(file, ec);
  return ec ? file : p.lexically_normal().string();
}

std::string replay_command(const std::string& file, const std::string& implementation_spec) {
  return vgc_environment_prefix() + program_command() + " replay " + shell_quote(absolute_file(file)) + " --impl " +
         shell_quote(implementation_spec);
}

std::string replay_command(const std::string& file, const ReportContext& ctx) {
  return ctx.environment_prefix.value_or(vgc_environment_prefix()) + program_command() + " replay " +
         shell_quote(absolute_file(file)) + " --impl " + shell_quote(ctx.implementation_spec);
}

std::string render_counterexample(const ClauseOutcome& co, const ReportContext& ctx) {
  const std::string file = (fs::path(ctx.run_dir) / counterexample_path(co)).string();
  std::string out;
  out += "# vgc counterexample for " + std::string(co.clause->id) + " (" +
         std::string(clause_level_name(co.clause->level)) + "): " + clause_status_name(co.status) + "\n";
  out += "# implementation: " + ctx.implementation_spec + "\n";
  out += "# found by property " + co.found_by + " with seed " + std::to_string(co.seed) + "\n";
  std::string msg = co.finding ? co.finding->message : "";
  for (auto& ch : msg)
    if (ch == '\n') ch = ' ';
  out += "# finding: " + msg + "\n";
  out += "# spec (" + std::string(co.clause->source) + "): " + std::string(co.clause->text) + "\n";
  out += "# replay: " + replay_command(file, ctx) + "\n";
  if (co.program.request) {
    out += "# " + commands_counted(co.program.commands.size()) +
           " from a fresh node; then the check of the capability \"" + co.program.request->capability +
           "\" (variant " + std::to_string(co.program.request->variant) +
           ") shows it. The last line (\"#! capability\") tells vgc replay to repeat that check.\n";
  } else {
    out += "# " + commands_counted(co.program.commands.size()) + " from a fresh node; the last one shows it.\n";
  }
  out += print_program(co.program);
  return out;
}

bool write_report(const std::string& reports_root, const RunResult& run, const Verdict& v,
                  const ReportContext& ctx, std::string* error) {
  std::error_code ec;
  const fs::path final_dir(ctx.run_dir);
  // The files go into a temporary sibling, then one rename puts them in
  // place of the run directory, which is absent or the empty one this run
  // claimed (claim_run_dir): a run directory is whole or absent, and never
  // another run's.
  const fs::path tmp_dir = final_dir.parent_path() / ("." + final_dir.filename().string() + "." +
                                                      std::to_string(::getpid()) + ".partial");
  fs::remove_all(tmp_dir, ec);
  fs::create_directories(tmp_dir / "counterexamples", ec);
  if (ec) {
    *error = "cannot create " + tmp_dir.string() + ": " + ec.message();
    return false;
  }
  auto fail = [&](const std::string& what) {
    *error = what;
    std::error_code ignored;
    fs::remove_all(tmp_dir, ignored);
    fs::remove(final_dir, ignored);  // the claimed directory, if still empty
    return false;
  };
  std::string e;
  const auto write_counterexample = [&](const ClauseOutcome& co) {
    if (!write_file(tmp_dir / counterexample_path(co), escape_unprintable(render_counterexample(co, ctx)), &e))
      return false;
    const FindingPicture picture = picture_of_finding(co);
    return !picture.has_mesh ||
           write_file(tmp_dir / counterexample_obj_path(co),
                      render_obj(picture.mesh, "vgc counterexample " + std::string(co.clause->id) +
                                                   ": the reference's final state after its commands"),
                      &e);
  };
  for (const ClauseOutcome& co : run.clauses) {
    if (!co.finding) continue;
    if (!write_counterexample(co)) return fail(e);
    for (const ClauseOutcome& other : co.other_findings)
      if (other.finding && !write_counterexample(other)) return fail(e);
  }
  if (!write_file(tmp_dir / "report.json", render_report_json(run, v, ctx), &e)) return fail(e);
  // What a person or a CI reads shows foreign bytes escaped (display_text.h).
  if (!write_file(tmp_dir / "junit.xml", escape_unprintable(render_junit(run, v, ctx)), &e)) return fail(e);
  if (!write_file(tmp_dir / "summary.md", escape_unprintable(render_summary(run, v, ctx)), &e)) return fail(e);
  if (!write_file(tmp_dir / "report.html", escape_unprintable(render_report_html(run, v, ctx)), &e)) return fail(e);
  fs::rename(tmp_dir, final_dir, ec);  // replaces an empty directory, never a full one
  if (ec) return fail("cannot move the report into " + final_dir.string() + ": " + ec.message());

  // reports/latest -> the run directory, now whole, replaced atomically
  // (a link under a name of this process's own, then one rename).
  const fs::path latest = fs::path(reports_root) / "latest";
  const fs::path tmp_link = fs::path(reports_root) / (".latest." + std::to_string(::getpid()) + ".partial");
  fs::remove(tmp_link, ec);
  const fs::path target = fs::relative(fs::absolute(final_dir), fs::absolute(reports_root), ec);
  fs::create_directory_symlink(ec ? fs::absolute(final_dir) : target, tmp_link, ec);
  if (!ec) fs::rename(tmp_link, latest, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp_link, ignored);
    *error = "report written to " + final_dir.string() + ", but reports/latest could not be updated: " + ec.message();
    return false;
  }
  return true;
}

}  // namespace vgc
