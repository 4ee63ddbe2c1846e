// open_impl.cpp — see open_impl.h.
#include "open_impl.h"

#include <fmt/core.h>

#if __has_include("capability_checks.h")
#include "capability_checks.h"
#define VGC_HAVE_CAPABILITY_CHECKS 1
#endif

namespace vgc::cli {

std::unique_ptr<Implementation> open_impl_or_report(const char* subcommand, const std::string& spec,
                                                    double timeout_seconds) {
  OpenOptions open;
  open.timeout_seconds = timeout_seconds;
  std::string error;
  auto sut = open_implementation(spec, open, &error);
  if (!sut) fmt::print(stderr, "vgc {}: {}\n", subcommand, error);
  return sut;
}

bool register_oracle_checks() {
#ifdef VGC_HAVE_CAPABILITY_CHECKS
  register_capability_checks();  // the oracles judge the optional capabilities
  return true;
#else
  return false;
#endif
}

}  // namespace vgc::cli
