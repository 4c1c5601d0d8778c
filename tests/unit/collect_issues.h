// Test helper: keeps every run-time issue the runtime or the VM reports.
#pragma once

#include <vector>

#include "runtime/machine.h"

namespace ncc {

class CollectIssues final : public RuntimeIssues {
 public:
  void issue(const RuntimeIssue& i) override { list.push_back(i); }
  std::vector<RuntimeIssue> list;
};

}  // namespace ncc
