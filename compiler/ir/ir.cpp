#include "ir.h"

#include <set>
#include <string_view>

namespace ncc::ir {

// A stream may have dropped millions of labelled blocks: the checks and the lowering
// look up only those the unit's held blocks name — a jump's or block range's target,
// a block of its own a call names (Macro B M97, "unit/label") — or all of them when a
// computed jump may go to any.
std::vector<size_t> Unit::named_streamed_labels() const {
  std::vector<size_t> out;
  if (streamed_labels.empty()) return out;
  const std::string own = name + "/";
  std::set<std::string_view> named;
  bool any = false;
  for (const Block& b : blocks)
    for (const Stmt& s : b.stmts) {
      if (s.kind == StmtKind::Jump) any = any || s.label.empty();
      if (s.kind == StmtKind::Jump || s.kind == StmtKind::CallRange) named.insert(s.label);
      if (s.kind == StmtKind::CallRange) named.insert(s.end_label);
      if (s.kind == StmtKind::Call && s.label.starts_with(own))
        named.insert(std::string_view(s.label).substr(own.size()));
    }
  if (!any && named.empty()) return out;
  for (size_t i = 0; i < streamed_labels.size(); ++i)
    if (any || named.count(streamed_labels[i].label())) out.push_back(i);
  return out;
}

}  // namespace ncc::ir
