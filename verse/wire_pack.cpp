// wire_pack.cpp — see wire_pack.h.
#include "wire_pack.h"

#include <cstring>

namespace vgc::verse {

void PackWriter::u8(std::uint8_t v) { out_->push_back(static_cast<char>(v)); }
void PackWriter::u16(std::uint16_t v) {
  u8(static_cast<std::uint8_t>(v >> 8));
  u8(static_cast<std::uint8_t>(v));
}
void PackWriter::u32(std::uint32_t v) {
  u16(static_cast<std::uint16_t>(v >> 16));
  u16(static_cast<std::uint16_t>(v));
}
void PackWriter::f32(float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  u32(bits);
}
void PackWriter::f64(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  // r6 (v_pack.c vnp_raw_pack_real64) packs the two 32-bit halves of the
  // double in memory order; on the little-endian machines r6 runs on that is
  // the low half first (docs/verse_wire.md section 1).
  u32(static_cast<std::uint32_t>(bits));
  u32(static_cast<std::uint32_t>(bits >> 32));
}
void PackWriter::bytes(const std::uint8_t* data, std::size_t n) {
  out_->append(reinterpret_cast<const char*>(data), n);
}
void PackWriter::string(const std::string& s) {
  out_->append(s);
  u8(0);
}

bool PackReader::u8(std::uint8_t* v) {
  if (remaining() < 1) return false;
  *v = data_[pos_++];
  return true;
}
bool PackReader::u16(std::uint16_t* v) {
  if (remaining() < 2) return false;
  *v = static_cast<std::uint16_t>((data_[pos_] << 8) | data_[pos_ + 1]);
  pos_ += 2;
  return true;
}
bool PackReader::u32(std::uint32_t* v) {
  if (remaining() < 4) return false;
  *v = (std::uint32_t{data_[pos_]} << 24) | (std::uint32_t{data_[pos_ + 1]} << 16) |
       (std::uint32_t{data_[pos_ + 2]} << 8) | std::uint32_t{data_[pos_ + 3]};
  pos_ += 4;
  return true;
}
bool PackReader::f32(float* v) {
  std::uint32_t bits;
  if (!u32(&bits)) return false;
  std::memcpy(v, &bits, 4);
  return true;
}
bool PackReader::f64(double* v) {
  if (remaining() < 8) return false;
  std::uint32_t hi = 0, lo = 0;
  u32(&lo);  // low half first, as f64() writes it
  u32(&hi);
  const std::uint64_t bits = (std::uint64_t{hi} << 32) | lo;
  std::memcpy(v, &bits, 8);
  return true;
}
bool PackReader::bytes(std::uint8_t* out, std::size_t n) {
  if (remaining() < n) return false;
  std::memcpy(out, data_ + pos_, n);
  pos_ += n;
  return true;
}
bool PackReader::string(std::string* s, std::size_t max_with_nul) {
  const std::size_t limit = remaining() < max_with_nul ? remaining() : max_with_nul;
  const void* nul = std::memchr(data_ + pos_, 0, limit);
  if (nul == nullptr) return false;
  const std::size_t n = static_cast<const std::uint8_t*>(nul) - (data_ + pos_);
  s->assign(reinterpret_cast<const char*>(data_ + pos_), n);
  pos_ += n + 1;
  return true;
}

}  // namespace vgc::verse
