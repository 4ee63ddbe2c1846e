// reference_wrapper.h — a test double: the reference node behind the
// adapter boundary (implementation.h) with every call forwarded, for tests
// that make one call misbehave the way a real host might (answer `done`,
// pick another free id, print a document differently) and override only
// that call. It claims no optional capability (request() is the default).
#pragma once

#include "implementation.h"
#include "reference_implementation.h"

namespace vgc::test {

class ReferenceWrapper : public Implementation {
 public:
  Answer reset() override { return inner_.reset(); }
  Answer apply(const Command& c) override { return inner_.apply(c); }
  Document snapshot() override { return inner_.snapshot(); }
  Document derived() override { return inner_.derived(); }

 protected:
  ReferenceImplementation inner_;
};

}  // namespace vgc::test
