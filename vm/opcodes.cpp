#include "opcodes.h"

#include <array>

namespace ncc::vm {

namespace {
constexpr std::array<OpInfo, static_cast<size_t>(Op::Count)> kOps = {{
#define NCC_OP_INFO(name, format, pop, push, doc) {#name, format, pop, push, doc},
    NCC_OPCODES(NCC_OP_INFO)
#undef NCC_OP_INFO
}};

constexpr std::array<int, static_cast<size_t>(Op::Count)> make_sizes() {
  std::array<int, static_cast<size_t>(Op::Count)> sizes{};
  for (size_t i = 0; i < kOps.size(); ++i) {
    int size = 1;
    for (char f : kOps[i].format) size += operand_size(f);
    sizes[i] = size;
  }
  return sizes;
}
constexpr auto kSizes = make_sizes();
}  // namespace

const OpInfo& op_info(Op op) { return kOps[static_cast<size_t>(op)]; }
int instruction_size(Op op) { return kSizes[static_cast<size_t>(op)]; }

}  // namespace ncc::vm
