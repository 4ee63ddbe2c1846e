// command_fields.h — the one field-by-field schema of every command.
//
// Spec: docs/spec_facts.md, "Command set of the geometry node" (field
// order and widths of protocol commands 48..64).
//
// Rationale: the text codec, the binary codec, bit-exact equality and the
// random generators all walk a command's fields in the same order. Writing
// that order once, here, means a field added to a command cannot be printed
// but not parsed, or encoded but not compared.
//
// visit_fields(c, v) calls v(name, field, hint) for each field in wire order,
// where field is a reference to an integer, float, double, std::string or
// std::array of those, and hint says how the text form shows it.
#pragma once

#include "command.h"

namespace vgc {

enum class FieldHint { Plain, LayerType, RealFormat };

template <class V> void visit_fields(cmd::LayerCreate& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("name", c.name, FieldHint::Plain);
  v("type", c.type, FieldHint::LayerType);
  v("def_uint", c.def_uint, FieldHint::Plain);
  v("def_real", c.def_real, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::LayerDestroy& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::LayerSubscribe& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("real_format", c.real_format, FieldHint::RealFormat);
}
template <class V> void visit_fields(cmd::LayerUnsubscribe& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexSetXyzReal32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("vertex_id", c.vertex_id, FieldHint::Plain);
  v("x", c.x, FieldHint::Plain);
  v("y", c.y, FieldHint::Plain);
  v("z", c.z, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexSetXyzReal64& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("vertex_id", c.vertex_id, FieldHint::Plain);
  v("x", c.x, FieldHint::Plain);
  v("y", c.y, FieldHint::Plain);
  v("z", c.z, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexDelete& c, V&& v) {
  v("vertex_id", c.vertex_id, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexSetUint32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("vertex_id", c.vertex_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexSetReal64& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("vertex_id", c.vertex_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::VertexSetReal32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("vertex_id", c.vertex_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetCornerUint32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("v", c.v, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetCornerReal64& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("v", c.v, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetCornerReal32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("v", c.v, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonDelete& c, V&& v) {
  v("polygon_id", c.polygon_id, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetFaceUint8& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetFaceUint32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetFaceReal64& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::PolygonSetFaceReal32& c, V&& v) {
  v("layer_id", c.layer_id, FieldHint::Plain);
  v("polygon_id", c.polygon_id, FieldHint::Plain);
  v("value", c.value, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::CreaseSetVertex& c, V&& v) {
  v("layer", c.layer, FieldHint::Plain);
  v("def_crease", c.def_crease, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::CreaseSetEdge& c, V&& v) {
  v("layer", c.layer, FieldHint::Plain);
  v("def_crease", c.def_crease, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::BoneCreate& c, V&& v) {
  v("bone_id", c.bone_id, FieldHint::Plain);
  v("weight", c.weight, FieldHint::Plain);
  v("reference", c.reference, FieldHint::Plain);
  v("parent", c.parent, FieldHint::Plain);
  v("pos", c.pos, FieldHint::Plain);
  v("pos_label", c.pos_label, FieldHint::Plain);
  v("rot", c.rot, FieldHint::Plain);
  v("rot_label", c.rot_label, FieldHint::Plain);
}
template <class V> void visit_fields(cmd::BoneDestroy& c, V&& v) {
  v("bone_id", c.bone_id, FieldHint::Plain);
}

// Read-only walk for printers and comparisons.
template <class C, class V> void visit_fields_const(const C& c, V&& v) {
  visit_fields(const_cast<C&>(c), v);
}

}  // namespace vgc
