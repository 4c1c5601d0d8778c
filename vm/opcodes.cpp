#include "opcodes.h"

#include <array>

namespace ncc::vm {

namespace {
constexpr std::array<OpInfo, static_cast<size_t>(Op::Count)> kOps = {{
#define NCC_OP_INFO(name, format, pop, push, doc) {#name, format, pop, push, doc},
    NCC_OPCODES(NCC_OP_INFO)
#undef NCC_OP_INFO
}};
constexpr std::array<OpInfo, kServiceCount> kServiceOps = {{
#define SERVICE(name, printed, format, pop, push, device, doc) {printed, "h" format, pop, push, doc},
#include "contract/services.def"
#undef SERVICE
}};
static_assert(kOps[static_cast<size_t>(Op::Service)].format == "h");
}  // namespace

const OpInfo& op_info(Op op) { return kOps[static_cast<size_t>(op)]; }
const OpInfo& service_op_info(Service s) { return kServiceOps[static_cast<size_t>(s)]; }

}  // namespace ncc::vm
