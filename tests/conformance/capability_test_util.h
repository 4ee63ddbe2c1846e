// capability_test_util.h — shared by the tests of the optional capabilities
// (capability_test, report_test, no_oracle_test): the reference with its
// capability requests switched off, and the catalog's capability names and
// clauses, read from the property catalog so the tests follow it.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "implementation.h"
#include "property.h"
#include "reference_implementation.h"
#include "reference_wrapper.h"

namespace vgc::test {

// The reference with the default Implementation::request ("not
// supported"): an implementation that predates the requests, so it claims
// no optional capability.
class ReferenceClaimingNothing final : public ReferenceWrapper {
 public:
  std::string name() const override { return "claims-nothing"; }
};

// The capability names the catalog's properties declare, sorted.
inline std::vector<std::string> catalog_capabilities() {
  std::set<std::string> names;
  for (const PropertySpec& p : property_catalog())
    if (!p.capability.empty()) names.insert(std::string(p.capability));
  return {names.begin(), names.end()};
}

// The clauses the capability properties declare.
inline std::set<std::string> capability_clause_ids() {
  std::set<std::string> ids;
  for (const PropertySpec& p : property_catalog())
    if (!p.capability.empty())
      for (auto c : p.clauses) ids.insert(std::string(c));
  return ids;
}

}  // namespace vgc::test
