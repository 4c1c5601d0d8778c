#include "opcodes.h"

#include <array>

namespace ncc::vm {

namespace {
constexpr std::array<OpInfo, static_cast<size_t>(Op::Count)> kOps = {{
#define NCC_OP_INFO(name, format, pop, push, doc) {#name, format, pop, push, doc},
    NCC_OPCODES(NCC_OP_INFO)
#undef NCC_OP_INFO
}};
}  // namespace

const OpInfo& op_info(Op op) { return kOps[static_cast<size_t>(op)]; }

}  // namespace ncc::vm
