// login_address_test.cpp — a login's local address (docs/verse_wire.md
// section 2, "A login's address"; verse/login_address_quarantine.h): it
// stays bound after the login ends, and an accept encrypted under another
// key starts the login again from a new address.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <map>
#include <set>
#include <thread>

#include "login_address_quarantine.h"
#include "running_host.h"
#include "verse_client.h"
#include "wire_endpoint.h"
#include "wire_login.h"

namespace vgc::verse {
namespace {

// Whether a new socket can bind 0.0.0.0:port now.
bool port_is_free(std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_ANY);
  const bool ok = ::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0;
  ::close(fd);
  return ok;
}

// The campaign's failure (fuzz_wire_campaign, a fresh clone): a login
// given the port of an earlier one whose host record was still pending was
// answered with that record's accept. No later login may be given it.
TEST(LoginAddress, StaysBoundAfterTheLoginEnds) {
  RunningHost h;
  std::uint16_t port = 0;
  {
    ClientSession s;
    const Status st = s.connect("127.0.0.1", h.host.port(), {});
    ASSERT_TRUE(st.ok()) << st.to_string();
    port = s.local_port();
    ASSERT_NE(port, 0);
    s.disconnect("done");
  }
  EXPECT_FALSE(port_is_free(port)) << "port " << port << " was freed when its login ended";
  EXPECT_GE(quarantined_login_sockets(), 1u);
}

// A host that answers the first address's login with an accept no key of
// ours decrypts (a block above every modulus), and the next address's
// properly: the client logs in, from a second address.
TEST(LoginAddress, AnAcceptForAnotherKeyStartsAgainFromANewAddress) {
  UdpSocket host;
  ASSERT_TRUE(host.open("127.0.0.1", 0).ok());
  const std::uint16_t host_port = host.port();
  const RsaKey host_key = make_rsa_key();
  std::atomic<bool> stop{false};
  std::set<std::string> logins_from;
  std::thread serve([&] {
    std::map<std::string, login::Contact> contacts;
    std::string first_address;
    while (!stop) {
      std::string bytes;
      PeerAddress from;
      if (!host.receive(&bytes, &from, 0.05).ok()) continue;
      LoginMessage m;
      if (!parse_login_packet(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &m).ok()) continue;
      if (const auto* c = std::get_if<login::Contact>(&m)) {
        contacts[from.to_string()] = *c;
        login::Challenge ch;
        ch.e = host_key.e;
        ch.n = host_key.n;
        (void)host.send_to(from, build_login_packet(ch));
      } else if (std::holds_alternative<login::Login>(m)) {
        if (first_address.empty()) first_address = from.to_string();
        const bool first = from.to_string() == first_address;
        logins_from.insert(from.to_string());
        login::Accept a;
        a.avatar = 7;
        if (first) {
          a.encrypted_data_key.fill(0xFF);  // not below any 512-bit modulus
        } else {
          KeyBytes data_key{};
          data_key[5] = 1;
          ASSERT_TRUE(rsa_apply(data_key, contacts[from.to_string()].e, contacts[from.to_string()].n,
                                &a.encrypted_data_key)
                          .ok());
        }
        (void)host.send_to(from, build_login_packet(a));
      }
    }
  });
  ClientSession s;
  ClientOptions o;
  o.login_timeout_s = 20;
  const Status st = s.connect("127.0.0.1", host_port, o);
  stop = true;
  serve.join();
  ASSERT_TRUE(st.ok()) << st.to_string();
  EXPECT_EQ(s.avatar(), 7u);
  EXPECT_EQ(logins_from.size(), 2u);
}

}  // namespace
}  // namespace vgc::verse
