// wire_status.cpp — see wire_status.h.
#include "wire_status.h"

#include <cstdio>

namespace vgc::verse {

const char* Status::code_name() const {
  switch (code) {
    case Code::Ok: return "ok";
    case Code::ProtocolError: return "protocol-error";
    case Code::Timeout: return "timeout";
    case Code::NetworkError: return "network-error";
    case Code::Closed: return "closed";
    case Code::Dropped: return "dropped";
  }
  return "unknown";
}

std::string Status::to_string() const {
  if (detail.empty()) return code_name();
  return std::string(code_name()) + ": " + detail;
}

std::string seconds_text(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g s", seconds);
  return buffer;
}

}  // namespace vgc::verse
