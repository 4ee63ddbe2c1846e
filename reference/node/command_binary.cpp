// command_binary.cpp — see command_binary.h.
#include "command_binary.h"

#include <cstring>
#include <type_traits>

#include "command_fields.h"

namespace vgc {
namespace {

template <class T> void put_scalar(std::string& out, const T& v) {
  if constexpr (std::is_same_v<T, std::string>) {
    out += static_cast<char>(v.size());
    out += v;
  } else {
    using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
              std::conditional_t<sizeof(T) == 2, std::uint16_t,
              std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    U bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (std::size_t i = 0; i < sizeof bits; ++i) out += static_cast<char>((bits >> (8 * i)) & 0xFF);
  }
}

struct Encoder {
  std::string& out;
  bool ok = true;
  template <class T> void operator()(const char*, const T& v, FieldHint) {
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      for (const auto& e : v) put_scalar(out, e);
    } else {
      if constexpr (std::is_same_v<T, std::string>) {
        if (v.size() > 255) ok = false;
      }
      put_scalar(out, v);
    }
  }
};

struct Decoder {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos;
  DecodeStatus status = DecodeStatus::Ok;

  template <class T> void get_scalar(T& v) {
    if (status != DecodeStatus::Ok) return;
    if constexpr (std::is_same_v<T, std::string>) {
      if (pos >= size) {
        status = DecodeStatus::Truncated;
        return;
      }
      const std::size_t n = data[pos];
      if (size - pos - 1 < n) {
        status = DecodeStatus::Truncated;
        return;
      }
      v.assign(reinterpret_cast<const char*>(data + pos + 1), n);
      pos += 1 + n;
    } else {
      if (size - pos < sizeof(T)) {
        status = DecodeStatus::Truncated;
        return;
      }
      std::uint64_t bits = 0;
      for (std::size_t i = 0; i < sizeof(T); ++i) bits |= std::uint64_t{data[pos + i]} << (8 * i);
      using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                std::conditional_t<sizeof(T) == 2, std::uint16_t,
                std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
      const U narrow = static_cast<U>(bits);
      std::memcpy(&v, &narrow, sizeof v);
      pos += sizeof(T);
    }
  }
  template <class T> void operator()(const char*, T& v, FieldHint) {
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      for (auto& e : v) get_scalar(e);
    } else {
      get_scalar(v);
    }
  }
};

template <std::size_t I = 0> void emplace_index(std::size_t index, Command* out) {
  if constexpr (I < kCommandKinds) {
    if (index == I) {
      out->emplace<I>();
      return;
    }
    emplace_index<I + 1>(index, out);
  }
}

}  // namespace

const char* decode_status_name(DecodeStatus s) {
  switch (s) {
    case DecodeStatus::Ok: return "ok";
    case DecodeStatus::End: return "end";
    case DecodeStatus::BadTag: return "bad-tag";
    case DecodeStatus::Truncated: return "truncated";
  }
  return "?";
}

bool encode_command(const Command& c, std::string* out) {
  // Appended in place, taken back on failure (no buffer of its own: the
  // fuzz targets encode every command they run).
  const std::size_t start = out->size();
  *out += static_cast<char>(c.index());
  Encoder e{*out};
  std::visit([&](const auto& x) { visit_fields_const(x, e); }, c);
  if (!e.ok) {
    out->resize(start);
    return false;
  }
  return true;
}

DecodeStatus decode_command(const std::uint8_t* data, std::size_t size, std::size_t* pos, Command* out) {
  if (*pos >= size) return DecodeStatus::End;
  const std::size_t tag = data[*pos];
  if (tag >= kCommandKinds) return DecodeStatus::BadTag;
  Command c;
  emplace_index(tag, &c);
  Decoder d{data, size, *pos + 1};
  std::visit([&](auto& x) { visit_fields(x, d); }, c);
  if (d.status != DecodeStatus::Ok) return d.status;
  *pos = d.pos;
  *out = std::move(c);
  return DecodeStatus::Ok;
}

DecodeStatus decode_commands(const std::uint8_t* data, std::size_t size, std::vector<Command>* out) {
  out->reserve(out->size() + size / 8);  // most commands take 8 bytes or more
  std::size_t pos = 0;
  for (;;) {
    Command c;
    const DecodeStatus s = decode_command(data, size, &pos, &c);
    if (s != DecodeStatus::Ok) return s;
    out->push_back(std::move(c));
  }
}

}  // namespace vgc
