// wire_login.h — the r6 login: four unencrypted packets, RSA with 512-bit
// keys (GMP arithmetic), and the data key it hands over.
//
// Spec: docs/verse_wire.md section 2 (connect stages, key sizes, the name
// and password block, the data key), from r6 v_connect.c, v_encryption.c,
// v_connection.h.
//
// Rationale: the stage packets are built and parsed here and nowhere else,
// by the client (verse_client.cpp) and the host (verse_host.cpp) alike. The
// RSA step is textbook r6: c = m^e mod n on 64-byte big-endian numbers, no
// padding scheme (r6 has none); this is interoperability, not security.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>

#include "wire_packet.h"
#include "wire_status.h"

namespace vgc::verse {

inline constexpr std::size_t kKeyBytes = 64;            // 512 bits, r6 V_ENCRYPTION_LOGIN_KEY_SIZE
inline constexpr std::uint8_t kReleaseNumber = 6;       // r6 V_RELEASE_NUMBER, sent in stage 1
inline constexpr std::size_t kMaxLoginField = 31;       // name and password: 32 bytes with the NUL

using KeyBytes = std::array<std::uint8_t, kKeyBytes>;   // big-endian number

struct RsaKey {
  KeyBytes e{}, d{}, n{};  // public exponent, private exponent, modulus
};

// A fresh key: two random 256-bit primes with their top two bits set (so n
// has its top bit set and every 64-byte block below 0x80.. fits), e = 65537.
RsaKey make_rsa_key();
// out = data^exponent mod modulus. ProtocolError when data >= modulus or
// the modulus is zero (a hostile key), so the result is never garbage.
Status rsa_apply(const KeyBytes& data, const KeyBytes& exponent, const KeyBytes& modulus, KeyBytes* out);

// The 64-byte block the client encrypts in stage 2: name NUL-ended in bytes
// 0..31, password in 32..63, random padding after each NUL, last byte 0.
// false when a field is longer than kMaxLoginField or holds a NUL, or the
// name starts with a byte >= 0x80 (it must stay below any key's modulus).
bool make_login_block(const std::string& name, const std::string& password, KeyBytes* out);
// Reads name and password back; ProtocolError when a half has no NUL.
Status read_login_block(const KeyBytes& block, std::string* name, std::string* password);

// A fresh data key: random bytes, the first below 0x40 (r6 does the same so
// the key, as a number, is below the client's modulus).
DataKey make_data_key();

namespace login {
struct Contact { KeyBytes e{}, n{}; };                       // stage 0, client -> host: id 0, cmd 0
struct Challenge {                                          // stage 1, host -> client: id 0, cmd 0
  std::uint8_t version = kReleaseNumber;
  std::uint32_t seconds = 0, fraction = 0;                  // host time
  KeyBytes e{}, n{};                                        // host public key
};
struct Login { KeyBytes encrypted{}; };                      // stage 2, client -> host: id 1, cmd 0
struct Accept {                                             // host -> client: id 1, cmd 1
  std::uint32_t avatar = 0;
  KeyBytes encrypted_data_key{};
};
struct Terminate { std::string bye; };                       // cmd 2 (only parsed, never expected here)
}  // namespace login

using LoginMessage = std::variant<login::Contact, login::Challenge, login::Login, login::Accept, login::Terminate>;

std::string build_login_packet(const LoginMessage& m);
// Parses one login packet; ProtocolError naming what is wrong (wrong id,
// unknown stage, short key) for anything else.
Status parse_login_packet(const std::uint8_t* data, std::size_t size, LoginMessage* out);

}  // namespace vgc::verse
