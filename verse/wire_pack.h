// wire_pack.h — big-endian packing of the Verse r6 field types, with bounds.
//
// Spec: docs/verse_wire.md section 1 ("Field encodings": integers
// big-endian, a real32 as its IEEE-754 bits big-endian, a real64 as its low
// then its high 32 bits, each big-endian, strings NUL-ended).
//
// Rationale: PackWriter appends to a std::string; PackReader reads from a
// byte range and every read returns false (and reads nothing) when the
// bytes are not there, so a decoder cannot run past a packet. Strings are
// read up to their NUL and never longer than the remaining bytes or the
// caller's bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vgc::verse {

class PackWriter {
 public:
  explicit PackWriter(std::string* out) : out_(out) {}
  void u8(std::uint8_t v);
  void u16(std::uint16_t v);
  void u32(std::uint32_t v);
  void f32(float v);   // the float's bits as a u32
  void f64(double v);  // the double's low 32 bits, then its high 32 bits, each big-endian (r6 on little-endian)
  void bytes(const std::uint8_t* data, std::size_t n);
  // The string's bytes then a NUL. Precondition: no NUL inside (callers check).
  void string(const std::string& s);

 private:
  std::string* out_;
};

class PackReader {
 public:
  PackReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool u8(std::uint8_t* v);
  bool u16(std::uint16_t* v);
  bool u32(std::uint32_t* v);
  bool f32(float* v);
  bool f64(double* v);
  bool bytes(std::uint8_t* out, std::size_t n);
  // Reads up to and including a NUL found within min(max_with_nul, remaining)
  // bytes; false (nothing consumed) when there is none.
  bool string(std::string* s, std::size_t max_with_nul);
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return size_ - pos_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace vgc::verse
