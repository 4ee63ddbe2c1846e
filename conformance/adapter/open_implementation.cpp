// open_implementation.cpp — "reference", "exec:CMD", "plugin:PATH" to an Implementation.
#include "implementation.h"
#include "reference_implementation.h"

namespace vgc {

std::unique_ptr<Implementation> open_implementation(const std::string& spec, const OpenOptions&,
                                                    std::string* error) {
  if (spec == "reference") return std::make_unique<ReferenceImplementation>();
  *error = "unknown implementation '" + spec + "': expected reference, exec:CMD or plugin:PATH";
  return nullptr;
}

}  // namespace vgc
