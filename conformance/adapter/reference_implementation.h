// reference_implementation.h — the reference node behind the adapter boundary.
// Spec: as node.h. The in-process route ("--impl reference").
#pragma once

#include <memory>

#include "implementation.h"
#include "node.h"

namespace vgc {

class ReferenceImplementation final : public Implementation {
 public:
  std::string name() const override { return "reference"; }
  Answer reset() override;
  Answer apply(const Command& c) override;
  Document snapshot() override;
  Document derived() override;
  Document request(const std::string& line) override;  // capability_documents.h
  // Kept up to date command by command (NodeDigest): costs what a command changed.
  bool offers_digest() override { return true; }
  DigestAnswer digest() override { return {CallStatus::Ok, digest_.digests(), {}}; }
  const Node& node() const { return node_; }

 private:
  Node node_;
  NodeDigest digest_;
  ChangeLog changes_;
};

}  // namespace vgc
