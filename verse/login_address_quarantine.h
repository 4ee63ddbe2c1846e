// login_address_quarantine.h — a client's local address outlives its
// session at the host (docs/verse_wire.md section 2, "A login's address").
//
// A Verse host keeps what it knows of an address after the session there
// ends or a login there stalls: r6 keeps a pending login for 30 s and
// ignores a new contact from its address meanwhile (v_connection.c), and
// vgc's own host answers such a contact with the earlier login's challenge
// and accept. A new login from the same local port is then answered with
// an accept encrypted under the earlier login's key: either undecryptable
// or a wrong data key, a session that cannot talk. UDP has no TIME_WAIT,
// so a client picks its port afresh (bind to port 0) and the kernel may
// hand back a port it just freed.
//
// The client therefore keeps the port of every ended login bound, idle,
// for kQuarantineSeconds (longer than r6's 30 s), so no later login of any
// process on this machine is given it. At most kMaxQuarantined sockets are
// held (the oldest is released first), each with the smallest receive
// buffer, so a host resending to a dead session costs no memory.
#pragma once

#include <cstddef>

namespace vgc::verse {

inline constexpr double kQuarantineSeconds = 35.0;
inline constexpr std::size_t kMaxQuarantined = 256;

// Takes ownership of a bound UDP socket whose login ended (fd < 0: nothing).
void quarantine_login_socket(int fd);

// How many sockets are held now (after releasing those whose time is up).
std::size_t quarantined_login_sockets();

}  // namespace vgc::verse
