// adapter_test_util.h — shared helpers of tests/adapter: where the vgc
// binary, the plugins and the faulty programs are, and how to open them.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command_text.h"
#include "exec_implementation.h"
#include "implementation.h"

namespace vgc::test {

inline OpenOptions test_options(double timeout_seconds = 10.0) {
  OpenOptions o;
  o.timeout_seconds = timeout_seconds;
  o.vgc_binary = VGC_BINARY;
  return o;
}

// exec:'<vgc>' serve
inline std::string vgc_serve_spec() { return "exec:" + shell_quote(VGC_BINARY) + " serve"; }

// plugin:<build>/tests/adapter/plugins/lib<name>.so
inline std::string test_plugin(const std::string& name) {
  return std::string(VGC_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

// exec:sh '<source>/tests/adapter/faulty/<script>' <args>
inline std::string faulty_spec(const std::string& script, const std::string& args = "") {
  const std::string interpreter = script.size() > 3 && script.substr(script.size() - 3) == ".py" ? "python3" : "sh";
  return "exec:" + interpreter + " " + shell_quote(std::string(VGC_FAULTY_DIR) + "/" + script) +
         (args.empty() ? "" : " " + args);
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::vector<Command> cube_commands() {
  std::vector<Command> cs;
  TextError e;
  const bool ok = parse_commands(read_text(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc"), &cs, &e);
  EXPECT_TRUE(ok) << e.to_string();
  return cs;
}

// One line per answer: "ok", "rejected R", "error", or "<status>" for a failed call.
inline std::string answer_text(const Answer& a) {
  if (a.status != CallStatus::Ok) return std::string(call_status_name(a.status)) + ": " + a.detail;
  if (!a.verdict_reported) return "done";
  if (a.applied) return "ok";
  if (a.malformed) return "error";
  return "rejected " + a.reason;
}

}  // namespace vgc::test
