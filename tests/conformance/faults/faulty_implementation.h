// faulty_implementation.h — a FaultyNode behind the adapter boundary, in
// process (for the faults that neither crash nor hang).
#pragma once

#include <string>

#include "faulty_node.h"
#include "implementation.h"

namespace vgc::faults {

class FaultyImplementation final : public Implementation {
 public:
  explicit FaultyImplementation(int fault) : fault_(fault), node_(fault) {}
  std::string name() const override { return "fault:" + std::string(fault_catalog()[static_cast<std::size_t>(fault_)].name); }
  Answer reset() override {
    node_ = FaultyNode(fault_);
    return Answer{CallStatus::Ok, true, "", ""};
  }
  Answer apply(const Command& c) override {
    const FaultyAnswer a = node_.apply(c);
    return Answer{CallStatus::Ok, a.applied, a.reason, ""};
  }
  Document snapshot() override { return {CallStatus::Ok, node_.snapshot(), ""}; }
  Document derived() override { return {CallStatus::Ok, node_.derived(), ""}; }
  Document request(const std::string& line) override { return {CallStatus::Ok, node_.request(line), ""}; }

 private:
  int fault_;
  FaultyNode node_;
};

}  // namespace vgc::faults
