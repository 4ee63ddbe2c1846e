// minimize_finding.cpp — see minimize_finding.h.
#include "minimize_finding.h"

#include <memory>

#include "implementation.h"
#include "launched_host.h"
#include "program_text.h"
#include "runner.h"

namespace vgc::fuzz {

Minimized minimize_finding(const std::string& program_text, const std::string& clause, const std::string& impl_spec,
                           std::chrono::steady_clock::time_point deadline, int max_replays,
                           const std::string& status, const OpenOptions& open, const std::string& host_cmd) {
  Minimized m;
  Program program;
  TextError error;
  if (clause.empty() || !parse_program(program_text, &program, &error)) return m;
  std::string open_error;
  std::unique_ptr<Implementation> sut;
  if (host_cmd.empty()) {
    sut = open_implementation(impl_spec, open, &open_error);
  } else if (const std::optional<Route> route = parse_route(impl_spec, &open_error)) {
    sut = open_launched_host(*route, open, host_cmd, "", &open_error);
  }
  if (!sut) return m;
  auto shows = [&](const Program& p) {
    if (m.replays >= max_replays || std::chrono::steady_clock::now() >= deadline) return false;
    ++m.replays;
    const ReplayResult r = replay_program(p, *sut);
    return r.failure && r.failure->clause == clause &&
           (status.empty() || finding_status_name(r.failure->status) == status);
  };
  m.before = program.commands.size();
  if (!shows(program)) return m;
  m.reproduced = true;
  for (std::size_t chunk = std::max<std::size_t>(1, program.commands.size() / 2); chunk >= 1; chunk /= 2) {
    for (std::size_t at = 0; at < program.commands.size();) {
      Program fewer = program;
      fewer.commands.erase(fewer.commands.begin() + static_cast<std::ptrdiff_t>(at),
                           fewer.commands.begin() +
                               static_cast<std::ptrdiff_t>(std::min(program.commands.size(), at + chunk)));
      if (shows(fewer)) program = std::move(fewer);
      else at += chunk;
    }
    if (chunk == 1) break;
  }
  m.after = program.commands.size();
  m.text = print_program(program);
  return m;
}

}  // namespace vgc::fuzz
