// fault_plugin.cpp — libvgc_fault_plugin.so: a FaultyNode behind the plugin
// C ABI (vgc_plugin.h). The fault is named by the environment variable
// VGC_FAULT (see faulty_node.cpp for the list), so one library serves every
// fault, through every route:
//   VGC_FAULT=bone-cycles-accepted ./vgc certify --impl plugin:build/tests/conformance/libvgc_fault_plugin.so
// It exports no vgc_plugin_request_v1, so it claims no optional capability.
// Built with VGC_FAULT_PLUGIN_REQUESTS (libvgc_fault_plugin_requests.so) it
// also answers the capability requests, so the capability faults reach
// certify and replay through the plugin route:
//   VGC_FAULT=subdivision-ignores-creases ./vgc certify --impl plugin:PATH
// with PATH build/tests/conformance/libvgc_fault_plugin_requests.so.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

#include "command_text.h"
#include "faulty_node.h"
#include "vgc_plugin.h"

struct vgc_node {
  vgc::faults::FaultyNode node;
  std::string text;
};

namespace {

// VGC_FAULT: one fault name or a comma-separated list ("a,b,c"); an unknown
// name is refused at create (the plugin answers no node), so a typo in a
// test never certifies the plain reference by accident.
std::vector<int> faults_from_env(bool* ok) {
  const char* list = std::getenv("VGC_FAULT");
  std::vector<int> faults;
  std::string error;
  *ok = vgc::faults::parse_fault_list(list ? list : "", &faults, &error);
  if (!*ok) std::fprintf(stderr, "libvgc_fault_plugin: VGC_FAULT: %s\n", error.c_str());
  return faults;
}

vgc_node* create_node() {
  bool ok = true;
  auto faults = faults_from_env(&ok);
  if (!ok) return nullptr;
  return new (std::nothrow) vgc_node{vgc::faults::FaultyNode(std::move(faults)), {}};
}
void destroy_node(vgc_node* n) { delete n; }

int apply_line(vgc_node* n, const char* line, const char** reason) {
  vgc::Command c;
  bool blank = false;
  vgc::TextError e;
  if (!vgc::parse_command_line(line, 1, &c, &blank, &e)) {
    n->text = e.to_string();
    *reason = n->text.c_str();
    return VGC_MALFORMED;
  }
  const auto a = n->node.apply(c);
  if (a.applied) return VGC_APPLIED;
  n->text = a.reason;
  *reason = n->text.c_str();
  return VGC_REJECTED;
}

const char* snapshot_of(vgc_node* n) {
  n->text = n->node.snapshot();
  return n->text.c_str();
}
const char* derived_of(vgc_node* n) {
  n->text = n->node.derived();
  return n->text.c_str();
}

const vgc_plugin_v1_table kTable = {VGC_PLUGIN_ABI_VERSION, "vgc faulty reference (VGC_FAULT)", create_node,
                                    destroy_node, apply_line, snapshot_of, derived_of};

}  // namespace

extern "C" __attribute__((visibility("default"))) const vgc_plugin_v1_table* vgc_plugin_v1(void) { return &kTable; }

#ifdef VGC_FAULT_PLUGIN_REQUESTS
// The optional capability requests, with the capability faults applied.
extern "C" __attribute__((visibility("default"))) const char* vgc_plugin_request_v1(vgc_node* n, const char* line) {
  try {
    n->text = n->node.request(line ? line : "");
    return n->text.c_str();
  } catch (const std::exception&) {
    return nullptr;
  }
}
#endif
