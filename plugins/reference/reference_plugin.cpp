// reference_plugin.cpp — the reference node behind the plugin C ABI
// (vgc_plugin.h, ABI v1): libvgc_reference_plugin.so.
//
// Spec: as reference/node/node.h; the ABI is docs/adapters.md "plugin:PATH".
//
// Rationale: certifying our own node through the plugin route (in process
// and isolated) checks the route itself: it must give exactly the answers
// and documents of the in-process reference. It also shows a third party a
// complete plugin. No exception crosses the C boundary: allocation failure
// is reported as VGC_MALFORMED / NULL.
#include <exception>
#include <new>
#include <string>

#include "capability_documents.h"
#include "command_text.h"
#include "derived_document.h"
#include "node.h"
#include "reason.h"
#include "snapshot.h"
#include "vgc_plugin.h"

struct vgc_node {
  vgc::Node node;
  std::string reason;    // valid until the next call on this node
  std::string document;  // likewise
};

namespace {

vgc_node* create_node() { return new (std::nothrow) vgc_node(); }

void destroy_node(vgc_node* n) { delete n; }

int apply_line(vgc_node* n, const char* line, const char** reason) {
  try {
    vgc::Command c;
    bool blank = false;
    vgc::TextError e;
    if (!vgc::parse_command_line(line, 1, &c, &blank, &e)) {
      n->reason = blank ? "line 1, column 1: expected a command, found an empty line or a comment" : e.to_string();
      *reason = n->reason.c_str();
      return VGC_MALFORMED;
    }
    const vgc::Reason r = n->node.apply(c);
    if (r == vgc::Reason::Ok) return VGC_APPLIED;
    n->reason = std::string(vgc::reason_name(r));
    *reason = n->reason.c_str();
    return VGC_REJECTED;
  } catch (const std::exception&) {
    *reason = "internal error";
    return VGC_MALFORMED;
  }
}

const char* snapshot_of(vgc_node* n) {
  try {
    n->document = vgc::print_snapshot(n->node);
    return n->document.c_str();
  } catch (const std::exception&) {
    return nullptr;
  }
}

const char* derived_of(vgc_node* n) {
  try {
    n->document = vgc::print_derived(n->node);
    return n->document.c_str();
  } catch (const std::exception&) {
    return nullptr;
  }
}

const vgc_plugin_v1_table kTable = {
    VGC_PLUGIN_ABI_VERSION, "vgc reference node (plugin)", create_node, destroy_node, apply_line, snapshot_of,
    derived_of,
};

}  // namespace

extern "C" VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v1(void) { return &kTable; }

// The optional capability requests (vgc_plugin.h, capability_documents.h).
extern "C" VGC_PLUGIN_EXPORT const char* vgc_plugin_request_v1(vgc_node* n, const char* line) {
  try {
    auto text = vgc::answer_capability_request(n->node, line ? line : "");
    n->document = text ? *text : "error unknown request\n";
    return n->document.c_str();
  } catch (const std::exception&) {
    return nullptr;
  }
}
