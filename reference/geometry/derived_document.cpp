// derived_document.cpp — see derived_document.h.
#include "derived_document.h"

#include "bone_pose.h"
#include "crease.h"
#include "number_text.h"

namespace vgc {
namespace {

std::string u32(std::uint32_t v) { return format_uint(v, 32); }
std::string u16(std::uint16_t v) { return format_uint(v, 16); }

}  // namespace

std::string print_derived(const Node& node) {
  std::string out = "vgc-derived 1\n";
  for (const auto& [id, slot] : node.vertices())
    out += "vertex_crease " + u32(id) + " " + u32(vertex_crease(node, id)) + "\n";
  for (const auto& [id, slot] : node.polygons())
    for (int c = 0; c < corner_count(slot); ++c)
      out += "edge_crease " + u32(id) + " " + std::to_string(c) + " " + u32(edge_crease(node, id, c)) + "\n";
  for (const auto& [id, pose] : bone_world_poses(node)) {
    out += "bone_pose " + u16(id);
    for (double v : pose.pos) out += " " + format_f64(v);
    for (double v : pose.rot) out += " " + format_f64(v);
    out += "\n";
  }
  out += "end\n";
  return out;
}

}  // namespace vgc
