// wire_packet.cpp — see wire_packet.h.
#include "wire_packet.h"

#include "wire_pack.h"

namespace vgc::verse {

namespace {

bool has_bone_command(const std::uint8_t* data, std::size_t size, std::size_t from) {
  for (std::size_t i = from; i < size; ++i)
    if (data[i] == 64) return true;  // a cheap over-approximation: only then is a second pass worth it
  return false;
}

// One pass in one bone_create form.
Status parse_packet_in(const std::uint8_t* data, std::size_t size, Packet* out, BoneForm bones) {
  out->commands.clear();
  PackReader r(data, size);
  if (!r.u32(&out->id))
    return Status::protocol_error("packet of " + std::to_string(size) + " bytes: shorter than its 4-byte id");
  if (size > kMaxPacketBytes)
    return Status::protocol_error("packet of " + std::to_string(size) + " bytes: longer than " +
                                  std::to_string(kMaxPacketBytes));
  std::size_t pos = 4;
  if (pos == size) return Status::protocol_error("packet " + std::to_string(out->id) + " holds no command");
  while (pos < size) {
    WireCommand c;
    std::size_t used = 0;
    Status st = decode_command(data + pos, size - pos, &used, &c, bones);
    if (!st.ok())
      return Status::protocol_error("packet " + std::to_string(out->id) + ", command at byte " + std::to_string(pos) +
                                    ": " + st.detail);
    out->commands.push_back(std::move(c));
    pos += used;
  }
  return {};
}

}  // namespace

Status parse_packet(const std::uint8_t* data, std::size_t size, Packet* out, BoneForm bones, bool either_bone_form) {
  Status st = parse_packet_in(data, size, out, bones);
  out->other_bone_form = false;
  if (st.ok() || !either_bone_form || size > kMaxPacketBytes || !has_bone_command(data, size, 4)) return st;
  Packet other;
  const BoneForm flip = bones == BoneForm::Spec ? BoneForm::R6 : BoneForm::Spec;
  if (!parse_packet_in(data, size, &other, flip).ok()) return st;
  *out = std::move(other);
  out->other_bone_form = true;
  return {};
}

std::string build_packet(std::uint32_t id, const std::string& encoded_commands) {
  std::string p;
  PackWriter w(&p);
  w.u32(id);
  p += encoded_commands;
  return p;
}

void xor_packet(std::uint8_t* data, std::size_t size, const DataKey& key) {
  if (size < 4) return;
  const std::uint32_t id = (std::uint32_t{data[0]} << 24) | (std::uint32_t{data[1]} << 16) |
                           (std::uint32_t{data[2]} << 8) | std::uint32_t{data[3]};
  const std::size_t start = key[id % kDataKeyBytes];
  for (std::size_t i = 4; i < size; ++i) data[i] ^= key[(i + start) % kDataKeyBytes];
}

void xor_packet(std::string* packet, const DataKey& key) {
  xor_packet(reinterpret_cast<std::uint8_t*>(packet->data()), packet->size(), key);
}

}  // namespace vgc::verse
