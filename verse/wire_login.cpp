// wire_login.cpp — see wire_login.h. Big numbers: GMP (libgmp-dev).
#include "wire_login.h"

#include <gmp.h>

#include <cstring>
#include <random>

#include "wire_pack.h"

namespace vgc::verse {
namespace {

struct Mpz {
  mpz_t v;
  Mpz() { mpz_init(v); }
  ~Mpz() { mpz_clear(v); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
};

void import_key(mpz_t z, const KeyBytes& b) { mpz_import(z, b.size(), 1, 1, 1, 0, b.data()); }

// Writes z (< 2^512) as 64 big-endian bytes.
void export_key(const mpz_t z, KeyBytes* out) {
  out->fill(0);
  std::size_t count = 0;
  std::uint8_t buf[kKeyBytes * 2] = {};
  mpz_export(buf, &count, 1, 1, 1, 0, z);
  if (count > kKeyBytes) count = kKeyBytes;  // cannot happen for z < n < 2^512
  std::memcpy(out->data() + (kKeyBytes - count), buf, count);
}

std::uint64_t random_u64() {
  static thread_local std::random_device device;
  return (std::uint64_t{device()} << 32) ^ device();
}

void random_prime(gmp_randstate_t rand, mpz_t p) {
  mpz_urandomb(p, rand, 256);
  mpz_setbit(p, 255);
  mpz_setbit(p, 254);
  mpz_nextprime(p, p);
}

}  // namespace

RsaKey make_rsa_key() {
  gmp_randstate_t rand;
  gmp_randinit_default(rand);
  gmp_randseed_ui(rand, static_cast<unsigned long>(random_u64()));
  Mpz p, q, phi, pm1, qm1, e, d, n, g;
  mpz_set_ui(e.v, 65537);
  for (;;) {
    random_prime(rand, p.v);
    random_prime(rand, q.v);
    if (mpz_cmp(p.v, q.v) == 0) continue;
    mpz_mul(n.v, p.v, q.v);
    if (mpz_sizeinbase(n.v, 2) != 512) continue;
    mpz_sub_ui(pm1.v, p.v, 1);
    mpz_sub_ui(qm1.v, q.v, 1);
    mpz_mul(phi.v, pm1.v, qm1.v);
    mpz_gcd(g.v, e.v, phi.v);
    if (mpz_cmp_ui(g.v, 1) != 0) continue;
    if (mpz_invert(d.v, e.v, phi.v) == 0) continue;
    break;
  }
  gmp_randclear(rand);
  RsaKey k;
  export_key(e.v, &k.e);
  export_key(d.v, &k.d);
  export_key(n.v, &k.n);
  return k;
}

Status rsa_apply(const KeyBytes& data, const KeyBytes& exponent, const KeyBytes& modulus, KeyBytes* out) {
  Mpz m, x, n, r;
  import_key(m.v, data);
  import_key(x.v, exponent);
  import_key(n.v, modulus);
  if (mpz_cmp_ui(n.v, 1) <= 0) return Status::protocol_error("RSA key with a modulus of 0 or 1");
  if (mpz_cmp(m.v, n.v) >= 0)
    return Status::protocol_error("RSA block is not below the key's modulus (the key is too small for it)");
  mpz_powm(r.v, m.v, x.v, n.v);
  export_key(r.v, out);
  return {};
}

bool make_login_block(const std::string& name, const std::string& password, KeyBytes* out) {
  for (const std::string* s : {&name, &password})
    if (s->size() > kMaxLoginField || s->find('\0') != std::string::npos) return false;
  if (!name.empty() && static_cast<std::uint8_t>(name[0]) >= 0x80) return false;
  for (auto& b : *out) b = static_cast<std::uint8_t>(random_u64());
  std::memcpy(out->data(), name.data(), name.size());
  (*out)[name.size()] = 0;
  std::memcpy(out->data() + 32, password.data(), password.size());
  (*out)[32 + password.size()] = 0;
  (*out)[kKeyBytes - 1] = 0;
  if (name.empty()) (*out)[0] = 0;
  return true;
}

Status read_login_block(const KeyBytes& block, std::string* name, std::string* password) {
  const auto* n_end = static_cast<const std::uint8_t*>(std::memchr(block.data(), 0, 32));
  const auto* p_end = static_cast<const std::uint8_t*>(std::memchr(block.data() + 32, 0, 32));
  if (!n_end || !p_end) return Status::protocol_error("login block: name or password without its NUL");
  name->assign(reinterpret_cast<const char*>(block.data()), n_end - block.data());
  password->assign(reinterpret_cast<const char*>(block.data() + 32), p_end - (block.data() + 32));
  return {};
}

DataKey make_data_key() {
  DataKey k;
  for (auto& b : k) b = static_cast<std::uint8_t>(random_u64());
  k[0] &= 0x3F;
  return k;
}

std::string build_login_packet(const LoginMessage& m) {
  std::string p;
  PackWriter w(&p);
  std::visit(
      [&](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, login::Contact>) {
          w.u32(0); w.u8(0); w.u8(0);
          w.bytes(v.e.data(), kKeyBytes); w.bytes(v.n.data(), kKeyBytes);
        } else if constexpr (std::is_same_v<V, login::Challenge>) {
          w.u32(0); w.u8(0); w.u8(1); w.u8(v.version); w.u32(v.seconds); w.u32(v.fraction);
          w.bytes(v.e.data(), kKeyBytes); w.bytes(v.n.data(), kKeyBytes);
        } else if constexpr (std::is_same_v<V, login::Login>) {
          w.u32(1); w.u8(0); w.u8(2);
          w.bytes(v.encrypted.data(), kKeyBytes);
        } else if constexpr (std::is_same_v<V, login::Accept>) {
          w.u32(1); w.u8(1); w.u32(v.avatar);
          w.bytes(v.encrypted_data_key.data(), kKeyBytes);
        } else {
          w.u32(0); w.u8(2); w.string(v.bye.substr(0, kMaxWireString - 1));
        }
      },
      m);
  return p;
}

Status parse_login_packet(const std::uint8_t* data, std::size_t size, LoginMessage* out) {
  PackReader r(data, size);
  std::uint32_t id = 0;
  std::uint8_t cmd = 0;
  if (!r.u32(&id) || !r.u8(&cmd)) return Status::protocol_error("login packet shorter than 5 bytes");
  auto short_packet = [&](const char* what) {
    return Status::protocol_error(std::string(what) + ": packet of " + std::to_string(size) + " bytes is too short");
  };
  if (cmd == 0) {
    std::uint8_t stage = 0;
    if (!r.u8(&stage)) return short_packet("connect");
    if (stage == 0) {
      login::Contact c;
      if (!r.bytes(c.e.data(), kKeyBytes) || !r.bytes(c.n.data(), kKeyBytes)) return short_packet("connect stage 0");
      *out = c;
      return {};
    }
    if (stage == 1) {
      login::Challenge c;
      if (!r.u8(&c.version) || !r.u32(&c.seconds) || !r.u32(&c.fraction) || !r.bytes(c.e.data(), kKeyBytes) ||
          !r.bytes(c.n.data(), kKeyBytes))
        return short_packet("connect stage 1");
      *out = c;
      return {};
    }
    if (stage == 2) {
      login::Login c;
      if (!r.bytes(c.encrypted.data(), kKeyBytes)) return short_packet("connect stage 2");
      *out = c;
      return {};
    }
    return Status::protocol_error("connect packet with unknown stage " + std::to_string(stage));
  }
  if (cmd == 1) {
    login::Accept a;
    if (!r.u32(&a.avatar) || !r.bytes(a.encrypted_data_key.data(), kKeyBytes)) return short_packet("connect_accept");
    *out = a;
    return {};
  }
  if (cmd == 2) {
    login::Terminate t;
    (void)r.string(&t.bye, kMaxWireString);  // r6 encrypts it with a key the client may not have: text is best effort
    *out = t;
    return {};
  }
  return Status::protocol_error("packet " + std::to_string(id) + " during login starts with command " +
                                std::to_string(cmd) + ", not a login command (0, 1 or 2)");
}

}  // namespace vgc::verse
