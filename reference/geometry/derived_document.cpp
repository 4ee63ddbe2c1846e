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

std::string derived_vertex_line(const Node& node, std::uint32_t vertex_id) {
  return "vertex_crease " + u32(vertex_id) + " " + u32(vertex_crease(node, vertex_id)) + "\n";
}

std::string derived_polygon_lines(const Node& node, std::uint32_t polygon_id, const Slot& polygon) {
  std::string out;
  for (int c = 0; c < corner_count(polygon); ++c)
    out += "edge_crease " + u32(polygon_id) + " " + std::to_string(c) + " " + u32(edge_crease(node, polygon_id, c)) +
           "\n";
  return out;
}

std::map<std::uint16_t, std::string> derived_bone_lines(const Node& node) {
  std::map<std::uint16_t, std::string> out;
  for (const auto& [id, pose] : bone_world_poses(node)) {
    std::string line = "bone_pose " + u16(id);
    for (double v : pose.pos) line += " " + format_f64(v);
    for (double v : pose.rot) line += " " + format_f64(v);
    out.emplace(id, line + "\n");
  }
  return out;
}

DerivedRule derived_rule_of(const Node& node, std::string_view line) {
  const std::size_t space = line.find(' ');
  const std::string_view kind = line.substr(0, space);
  if (kind == "vertex_crease") return vertex_crease_rule(node);
  if (kind == "edge_crease") return edge_crease_rule(node);
  if (kind != "bone_pose") return DerivedRule::None;
  const std::string_view rest = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
  std::uint32_t id = 0;
  // An id that is no bone id at all (malformed, or past 0xFFFF) names no bone.
  if (!parse_uint(rest.substr(0, rest.find(' ')), 16, &id)) return DerivedRule::BonePosePerBone;
  return bone_pose_rule(node, static_cast<std::uint16_t>(id));
}

DerivedRule derived_place_rule(std::string_view kind) {
  if (kind == "edge_crease") return DerivedRule::EdgePerCorner;
  if (kind == "bone_pose") return DerivedRule::BonePosePerBone;
  return DerivedRule::None;
}

std::string print_derived(const Node& node) {
  std::string out = kDerivedHeader;
  for (const auto& [id, slot] : node.vertices()) out += derived_vertex_line(node, id);
  for (const auto& [id, slot] : node.polygons()) out += derived_polygon_lines(node, id, slot);
  for (const auto& [id, line] : derived_bone_lines(node)) out += line;
  out += "end\n";
  return out;
}

}  // namespace vgc
