// reference_plugin_table.cpp — see reference_plugin_table.h.
#include "reference_plugin_table.h"

#include <cfloat>
#include <string>
#include <variant>

#include "command_text.h"
#include "derived_document.h"
#include "node.h"
#include "snapshot.h"

namespace vgc::fuzz {
namespace {

struct PluginNode {
  Node node;
  PluginFault fault = PluginFault::None;
  std::string reason, snapshot, derived;
};

// True when the seeded fault says to report APPLIED for `c` although the
// reference rejected it with `r` (and to store nothing).
bool fault_accepts(const PluginNode& n, const Command& c, Reason r) {
  if (n.fault == PluginFault::AcceptRepeatedCorners && r == Reason::BadPolygon) {
    const auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c);
    if (!p || p->layer_id != Node::kPolygonLayer) return false;
    const int k = p->v[3] == kNone32 ? 3 : 4;
    for (int i = 0; i < k; ++i)
      if (p->v[i] == kNone32 || n.node.vertices().count(p->v[i]) == 0) return false;
    return true;  // all corners live: BadPolygon came from a repeat
  }
  return false;
}

// True when the seeded fault says to skip `c` and report APPLIED.
bool fault_skips(const PluginNode& n, const Command& c) {
  if (n.fault == PluginFault::IgnoreReal32Delete) {
    const auto* v = std::get_if<cmd::VertexSetXyzReal32>(&c);
    return v && (v->x == FLT_MAX || v->y == FLT_MAX || v->z == FLT_MAX) &&
           n.node.vertices().count(v->vertex_id) != 0;
  }
  return false;
}

template <PluginFault F> vgc_node* create() {
  auto* n = new PluginNode;
  n->fault = F;
  return reinterpret_cast<vgc_node*>(n);
}

void destroy(vgc_node* node) { delete reinterpret_cast<PluginNode*>(node); }

int apply(vgc_node* node, const char* line, const char** reason) {
  auto* n = reinterpret_cast<PluginNode*>(node);
  Command c;
  bool blank = false;
  TextError error;
  if (!parse_command_line(line, 1, &c, &blank, &error) || blank) {
    n->reason = blank ? "blank line" : error.to_string();
    *reason = n->reason.c_str();
    return VGC_MALFORMED;
  }
  if (fault_skips(*n, c)) return VGC_APPLIED;
  const Reason r = n->node.apply(c);
  if (r == Reason::Ok || fault_accepts(*n, c, r)) return VGC_APPLIED;
  n->reason = std::string(reason_name(r));
  *reason = n->reason.c_str();
  return VGC_REJECTED;
}

const char* snapshot(vgc_node* node) {
  auto* n = reinterpret_cast<PluginNode*>(node);
  n->snapshot = print_snapshot(n->node);
  return n->snapshot.c_str();
}

const char* derived(vgc_node* node) {
  auto* n = reinterpret_cast<PluginNode*>(node);
  n->derived = print_derived(n->node);
  return n->derived.c_str();
}

template <PluginFault F> const vgc_plugin_v1_table kTable = {
    VGC_PLUGIN_ABI_VERSION,
    F == PluginFault::None                    ? "vgc reference (in-process table)"
    : F == PluginFault::AcceptRepeatedCorners ? "vgc reference with fault: accept repeated corners"
                                              : "vgc reference with fault: ignore real32 delete",
    &create<F>, &destroy, &apply, &snapshot, &derived};

}  // namespace

const vgc_plugin_v1_table* reference_plugin_table(PluginFault fault) {
  switch (fault) {
    case PluginFault::None: return &kTable<PluginFault::None>;
    case PluginFault::AcceptRepeatedCorners: return &kTable<PluginFault::AcceptRepeatedCorners>;
    case PluginFault::IgnoreReal32Delete: return &kTable<PluginFault::IgnoreReal32Delete>;
  }
  return nullptr;
}

}  // namespace vgc::fuzz
