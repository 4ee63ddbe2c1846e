// wire_status.h — the one result type of every step of the Verse wire layer.
//
// Spec: docs/verse_wire.md (the r6 wire protocol as vgc speaks it).
//
// Rationale: codecs, the packet parser, the login and the UDP endpoint never
// throw and never abort on what a peer sends: each step returns a Status.
// A malformed or hostile packet is Code::ProtocolError with a sentence
// saying what was wrong and where; a peer that stops answering is
// Code::Timeout; an operating-system failure (socket, bind, resolve) is
// Code::NetworkError; a peer that ended the session is Code::Closed, and a
// host that dropped this client's session (it sent connect_terminate: the
// session fell too far behind, went silent, ...) is Code::Dropped, with the
// host's words.
#pragma once

#include <string>
#include <utility>

namespace vgc::verse {

struct Status {
  enum class Code { Ok, ProtocolError, Timeout, NetworkError, Closed, Dropped };
  Code code = Code::Ok;
  std::string detail;  // empty when ok(); otherwise one line for a person

  bool ok() const { return code == Code::Ok; }
  static Status success() { return {}; }
  static Status protocol_error(std::string d) { return {Code::ProtocolError, std::move(d)}; }
  static Status timeout(std::string d) { return {Code::Timeout, std::move(d)}; }
  static Status network_error(std::string d) { return {Code::NetworkError, std::move(d)}; }
  static Status closed(std::string d) { return {Code::Closed, std::move(d)}; }
  static Status dropped(std::string d) { return {Code::Dropped, std::move(d)}; }
  // "ok", "protocol-error", "timeout", "network-error", "closed", "dropped".
  const char* code_name() const;
  // "<code_name>: <detail>" (just the code name when detail is empty).
  std::string to_string() const;
};

// A limit in seconds as a person reads it in a Status detail: "2 s",
// "0.25 s" (shortest form, "%g"), never "2.000000 s".
std::string seconds_text(double seconds);

}  // namespace vgc::verse
