// faulty_implementation.h — a FaultyNode behind the adapter boundary, in
// process (for the faults that neither crash nor hang).
#pragma once

#include <string>

#include "faulty_node.h"
#include "implementation.h"

namespace vgc::faults {

class FaultyImplementation final : public Implementation {
 public:
  explicit FaultyImplementation(int fault) : faults_{fault}, node_(fault) {}
  explicit FaultyImplementation(std::vector<int> faults) : faults_(std::move(faults)), node_(faults_) {}
  std::string name() const override { return "fault:" + fault_list_name(faults_); }
  Answer reset() override {
    node_ = FaultyNode(faults_);
    Answer a;
    a.applied = true;
    return a;
  }
  Answer apply(const Command& c) override {
    const FaultyAnswer f = node_.apply(c);
    Answer a;
    a.applied = f.applied;
    a.reason = f.reason;
    return a;
  }
  Document snapshot() override { return {CallStatus::Ok, node_.snapshot(), ""}; }
  Document derived() override { return {CallStatus::Ok, node_.derived(), ""}; }
  Document request(const std::string& line) override { return {CallStatus::Ok, node_.request(line), ""}; }
  // The digest of the documents it prints, faults and all (FaultyNode::
  // digests): certification compares digests after each command
  // (program_checker.h), so the faults are found through that path (but
  // those whose digest is not cheap: FaultyNode::digest_cheap).
  bool offers_digest() override { return node_.digest_cheap(); }
  DigestAnswer digest() override { return {CallStatus::Ok, node_.digests(), ""}; }

 private:
  std::vector<int> faults_;
  FaultyNode node_;
};

}  // namespace vgc::faults
