// snapshot_state.cpp — see snapshot_state.h.
#include "snapshot_state.h"

#include <cstring>
#include <string_view>
#include <vector>

#include "number_text.h"
#include "snapshot.h"

namespace vgc::verse {
namespace {

// Splits a line into tokens; a quoted string is one token (unescaped).
bool tokenize(std::string_view line, std::vector<std::string>* out) {
  out->clear();
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    if (line[i] == '"') {
      std::string s;
      std::size_t used = 0, error_at = 0;
      if (!parse_quoted(line.substr(i), &s, &used, &error_at)) return false;
      out->push_back(s);
      i += used;
      continue;
    }
    const std::size_t end = line.find(' ', i);
    const std::size_t stop = end == std::string_view::npos ? line.size() : end;
    out->emplace_back(line.substr(i, stop - i));
    i = stop;
  }
  return true;
}

int value_count(std::uint8_t type) {
  switch (static_cast<LayerType>(type)) {
    case LayerType::VertexXyz: return 3;
    case LayerType::PolygonCornerUint32:
    case LayerType::PolygonCornerReal: return 4;
    default: return 1;
  }
}
bool is_real_type(std::uint8_t type) {
  const auto t = static_cast<LayerType>(type);
  return t == LayerType::VertexXyz || t == LayerType::VertexReal || t == LayerType::PolygonCornerReal ||
         t == LayerType::PolygonFaceReal;
}
int uint_bits(std::uint8_t type) { return static_cast<LayerType>(type) == LayerType::PolygonFaceUint8 ? 8 : 32; }

bool parse_values(std::uint8_t type, const std::vector<std::string>& t, std::size_t first, vgc::Slot* s) {
  const int n = value_count(type);
  if (t.size() != first + static_cast<std::size_t>(n)) return false;
  for (int i = 0; i < n; ++i) {
    if (is_real_type(type)) {
      if (!parse_f64(t[first + i], &s->r[i])) return false;
    } else if (!parse_uint(t[first + i], uint_bits(type), &s->u[i])) {
      return false;
    }
  }
  return true;
}

bool u16_of(const std::string& s, std::uint16_t* v) {
  std::uint32_t x = 0;
  if (!parse_uint(s, 16, &x)) return false;
  *v = static_cast<std::uint16_t>(x);
  return true;
}

}  // namespace

bool LayerInfo::operator==(const LayerInfo& o) const {
  return name == o.name && type == o.type && def_uint == o.def_uint &&
         std::memcmp(&def_real, &o.def_real, sizeof def_real) == 0;
}

bool slot_equal(std::uint8_t type, const vgc::Slot& a, const vgc::Slot& b) {
  const int n = value_count(type);
  for (int i = 0; i < n; ++i) {
    if (is_real_type(type)) {
      if (std::memcmp(&a.r[i], &b.r[i], sizeof(double)) != 0) return false;
    } else if (a.u[i] != b.u[i]) {
      return false;
    }
  }
  return true;
}

vgc::Slot layer_default_slot(std::uint16_t layer_id, const LayerInfo& layer) {
  vgc::Slot s;
  const UsedDefaults used = used_defaults(layer_id, static_cast<LayerType>(layer.type));
  for (int i = 0; i < 4; ++i) {
    if (used.def_uint) s.u[i] = layer.def_uint;
    if (used.def_real) s.r[i] = layer.def_real;
  }
  return s;
}

Status parse_snapshot_state(const std::string& text, NodeState* out) {
  *out = NodeState{};
  std::size_t line_no = 0, pos = 0;
  bool header = false, end = false;
  std::vector<std::string> t;
  while (pos < text.size() && !end) {
    const std::size_t nl = text.find('\n', pos);
    const std::size_t stop = nl == std::string::npos ? text.size() : nl;
    std::string_view line(text.data() + pos, stop - pos);
    pos = stop + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    auto bad = [&](const char* why) {
      return Status::protocol_error("snapshot line " + std::to_string(line_no) + ": " + why + ": " +
                                    std::string(line.substr(0, 120)));
    };
    if (!tokenize(line, &t) || t.empty()) return bad("does not parse");
    const std::string& k = t[0];
    if (!header) {
      if (k != "vgc-snapshot") return bad("expected the header vgc-snapshot");
      header = true;
    } else if (k == "end") {
      end = true;
    } else if (k == "layer") {
      std::uint16_t id = 0;
      LayerInfo l;
      if (t.size() != 7 || !u16_of(t[1], &id) || !parse_layer_type_name(t[3], &l.type)) return bad("bad layer");
      l.name = t[2];
      if (t[4] != "-" && !parse_uint(t[4], 32, &l.def_uint)) return bad("bad def_uint");
      if (t[5] != "-" && !parse_f64(t[5], &l.def_real)) return bad("bad def_real");
      out->layers[id] = l;
    } else if (k == "crease_vertex" || k == "crease_edge") {
      vgc::CreaseSetting c;
      if (t.size() != 3 || !parse_uint(t[2], 32, &c.def_crease)) return bad("bad crease");
      c.layer = t[1];
      (k == "crease_vertex" ? out->crease_vertex : out->crease_edge) = c;
    } else if (k == "vertex" || k == "polygon" || k == "slot") {
      std::uint16_t lid = k == "vertex" ? 0 : 1;
      std::size_t first = 2;
      if (k == "slot") {
        if (t.size() < 3 || !u16_of(t[1], &lid)) return bad("bad slot");
        first = 3;
      }
      std::uint32_t eid = 0;
      auto layer = out->layers.find(lid);
      if (t.size() < first || !parse_uint(t[first - 1], 32, &eid) || layer == out->layers.end())
        return bad("bad element or unknown layer");
      vgc::Slot s;
      if (!parse_values(layer->second.type, t, first, &s)) return bad("bad values");
      out->slots[lid][eid] = s;
    } else if (k == "bone") {
      vgc::Bone b;
      std::uint16_t parent = 0;
      if (t.size() != 14 || !u16_of(t[1], &b.id) || !u16_of(t[4], &parent)) return bad("bad bone");
      b.weight = t[2];
      b.reference = t[3];
      b.parent = parent;
      for (int i = 0; i < 3; ++i)
        if (!parse_f64(t[5 + i], &b.pos[i])) return bad("bad bone position");
      b.pos_label = t[8];
      for (int i = 0; i < 4; ++i)
        if (!parse_f64(t[9 + i], &b.rot[i])) return bad("bad bone rotation");
      b.rot_label = t[13];
      out->bones[b.id] = b;
    } else {
      return bad("unknown line");
    }
  }
  if (!end) return Status::protocol_error("snapshot without its final line \"end\"");
  return {};
}

}  // namespace vgc::verse
