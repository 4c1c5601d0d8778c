// The ncc VM instruction set. This page is the whole VM: read it first.
//
// Code is a byte string. Each instruction is an opcode byte followed by its
// operands, little-endian, as its format says: one letter an operand, of the kinds
// NCC_OPERANDS lists below (its letter, its size and its meaning). The verifier checks
// the range of every operand by its kind (vm/module.cpp), the disassembler prints it.
// `pop` and `push` are the fixed stack effects the verifier checks.
//
// A machine block is built up and then run: CODE and WORD/WORDPOP fill the pending
// block, EXEC hands it to the motion runtime and clears it. An operator message is
// built up by SHOW* and shown by MESSAGE.
//
// Services (contract/services.def: NC-110 ASSET files, operator input, the user
// screen, processes): SERVICE h runs host service h, its own operands after h as the
// catalogue gives them, its stack effect the catalogue's. The VM hands it to the
// ServiceHost of its device (contract/services.h) and knows no device itself. A service
// may have to wait (a process for another): then the instruction is left to run again,
// its operands still on the stack, and the VM returns Blocked to the scheduler that
// runs the processes (vm/processes.h).
//
// Frames: CALLENTRY calls an entry point (again, while its count lasts), RETURN comes
// back; the local variables start afresh in every call (ARGs before it give some of
// them values), except in a CALLSHARED call (Macro B M98). CALLRANGE runs the code
// from one place to a RANGEEND (NC-110 EPP) and comes back after it; a range does
// not run inside another, and a jump out of it ends it.
#pragma once

#include <cstdint>
#include <string_view>

#include "contract/services.h"

namespace ncc::vm {

// The operand kinds: name, letter, bytes, what the value is (and the range the verifier
// allows it).
#define NCC_OPERANDS(X)                                                                             \
  X(Number, 'k', 4, "index into the number constants")                                              \
  X(String, 's', 4, "index into the strings (an ASSET service's: a file name, docs/asset.md)")      \
  X(Code, 'c', 2, "index into the program's codes")                                                 \
  X(Slot, 'w', 1, "word slot (contract/word_slots.h)")                                              \
  X(Target, 'j', 4, "code offset of an instruction")                                                \
  X(Entry, 'e', 2, "index into the entry points (process.start: a process entry; others: not one)") \
  X(Space, 'v', 1, "variable space (Load, Store, Arg, asset.bind: numbered; others: a memory)")     \
  X(Index, 'i', 4, "variable index, below the size of the space before it")                         \
  X(Builtin, 'b', 1, "builtin function of the instruction's arity (contract/builtins.h)")           \
  X(Format, 'f', 1, "memory format (contract/variables.h)")                                         \
  X(Bytes, 'n', 1, "a count of bytes, 1..255")                                                      \
  X(Relation, 'q', 1, "a comparison: 1 =, 2 <, 3 >, 4 not =")                                       \
  X(Type, 't', 1, "value type a value is shown as (contract/variables.h), not Unavailable")         \
  X(SysVar, 'y', 2, "system variable: its number << 8 | its index (contract/system_vars.def)")      \
  X(LoopDepth, 'd', 1, "a repeat-loop depth (0: outside every loop)")                               \
  X(Rule, 'r', 1, "index into the program's value rules (ProgramSemantics::value_rules)")           \
  X(Places, 'p', 1, "decimal places 0..9, then")                                                    \
  X(Digits, 'm', 4, "the digits, an i32: the number m / 10^p")                                      \
  X(Service, 'h', 1, "a host service (contract/services.def); its own operands follow")

// An X-macro list, then Count: clang-format would indent Count as a continuation.
// clang-format off
enum class Operand : uint8_t {
#define NCC_OPERAND_ENUM(kind, letter, size, doc) kind,
  NCC_OPERANDS(NCC_OPERAND_ENUM)
#undef NCC_OPERAND_ENUM
  Count
};
// clang-format on

#define NCC_OPCODES(X)                                                                                             \
  X(Nop, "", 0, 0, "do nothing")                                                                                   \
  X(Const, "k", 0, 1, "push numbers[k]")                                                                           \
  X(ConstDec, "pm", 0, 1, "push m / 10^p (a constant as written)")                                                 \
  X(Load, "vi", 0, 1, "push variable v[i]")                                                                        \
  X(LoadX, "v", 1, 1, "pop an index; push variable v[index]")                                                      \
  X(Store, "vi", 1, 0, "pop a value into variable v[i]")                                                           \
  X(StoreX, "v", 2, 0, "pop a value, then an index; store the value into v[index]")                                \
  X(Neg, "", 1, 1, "negate the top")                                                                               \
  X(Not, "", 1, 1, "1 if the top is 0, else 0")                                                                    \
  X(Add, "", 2, 1, "a + b")                                                                                        \
  X(Sub, "", 2, 1, "a - b")                                                                                        \
  X(Mul, "", 2, 1, "a * b")                                                                                        \
  X(Div, "", 2, 1, "a / b; division by zero is a run-time error")                                                  \
  X(Mod, "", 2, 1, "a mod b (sign of a); b = 0 is a run-time error")                                               \
  X(Pow, "", 2, 1, "a to the power b")                                                                             \
  X(Eq, "", 2, 1, "1 if a == b")                                                                                   \
  X(Ne, "", 2, 1, "1 if a != b")                                                                                   \
  X(Lt, "", 2, 1, "1 if a < b")                                                                                    \
  X(Le, "", 2, 1, "1 if a <= b")                                                                                   \
  X(Gt, "", 2, 1, "1 if a > b")                                                                                    \
  X(Ge, "", 2, 1, "1 if a >= b")                                                                                   \
  X(And, "", 2, 1, "1 if a and b are not 0")                                                                       \
  X(Or, "", 2, 1, "1 if a or b is not 0")                                                                          \
  X(Xor, "", 2, 1, "1 if exactly one of a, b is not 0")                                                            \
  X(Call1, "b", 1, 1, "apply the one-argument builtin b")                                                          \
  X(Call2, "b", 2, 1, "apply the two-argument builtin b to a, b")                                                  \
  X(Jump, "j", 0, 0, "go to j")                                                                                    \
  X(JumpIfNot, "j", 1, 0, "pop; go to j if it is 0")                                                               \
  X(JumpIf, "j", 1, 0, "pop; go to j if it is not 0")                                                              \
  X(JumpSkip, "j", 0, 0, "go to j if the block-skip switch of the runtime is on")                                  \
  X(Step, "", 0, 0, "count one executed block against --max-steps")                                                \
  X(Sync, "", 0, 0, "the block is evaluated once the motion before it has ended (NC-110 '#')")                     \
  X(Code, "c", 0, 0, "add G/M code c to the pending block")                                                        \
  X(CodeOf, "w", 1, 0, "pop a number; add the code of letter slot w with that number")                             \
  X(Word, "wk", 0, 0, "set word w of the pending block to numbers[k]")                                             \
  X(WordDec, "wpm", 0, 0, "set word w of the pending block to m / 10^p (a constant as written)")                   \
  X(WordPop, "w", 1, 0, "pop the value of word w of the pending block")                                            \
  X(Exec, "", 0, 0, "run the pending block on the motion runtime, then clear it")                                  \
  X(Comment, "s", 0, 0, "show strings[s] to the operator")                                                         \
  X(Repeat, "jk", 1, 0, "pop a count 0..numbers[k]; open a repeat loop, or go to j if it is 0")                    \
  X(EndRepeat, "j", 0, 0, "count down the innermost repeat loop; go to j while it runs")                           \
  X(Unloop, "d", 0, 0, "the next jump lands at repeat-loop depth d of its code: close deeper loops")               \
  X(CallEntry, "e", 1, 0, "pop a count 1..9999; call entry point e that many times, one after the other")          \
  X(CallRange, "jjd", 0, 0, "run the code from j1 (at loop depth d) to the RANGEEND at j2, then come back")        \
  X(RangeEnd, "", 0, 0, "the end of a range: come back if the innermost frame runs it")                            \
  X(Return, "", 0, 0, "return from a call")                                                                        \
  X(End, "", 0, 0, "end of the program unit")                                                                      \
  X(LoadMem, "vf", 1, 1, "pop an index; push the value of format f there in memory v")                             \
  X(StoreMem, "vf", 2, 0, "pop a value, then an index; store it in format f in memory v")                          \
  X(StoreText, "vs", 1, 0, "pop a byte index; write the bytes of strings[s] there in memory v")                    \
  X(CopyText, "vvn", 2, 0, "pop a source, then a target byte index; copy n bytes v2 -> v1")                        \
  X(EqText, "vs", 1, 1, "pop a byte index; 1 if memory v holds the bytes of strings[s] there")                     \
  X(EqMem, "vvn", 2, 1, "pop two byte indices; 1 if their n bytes (memories v1, v2) are equal")                    \
  X(GetSys, "y", 0, 1, "push system variable y of the runtime")                                                    \
  X(SetSys, "y", 1, 0, "pop a value into system variable y of the runtime")                                        \
  X(Show, "s", 0, 0, "append strings[s] to the pending message")                                                   \
  X(ShowValue, "t", 1, 0, "pop a value; append it to the pending message as type t shows")                         \
  X(ShowText, "vn", 1, 0, "pop a byte index; append n bytes of memory v to the pending message")                   \
  X(Message, "", 0, 0, "show the pending message to the operator, then clear it")                                  \
  X(Check, "wr", 1, 1, "fail at word w unless the top meets value rule r (a parameter's value)")                   \
  X(ZeroIfVacant, "", 1, 1, "a vacant top (an unset Macro B variable) reads as 0")                                 \
  X(Arg, "vi", 1, 0, "pop a value into local variable v[i] of the next CALLENTRY's frame")                         \
  X(CallShared, "e", 1, 0, "pop a count 1..9999; call entry point e that many times, keeping the caller's locals") \
  X(NoBlock, "", 1, 0, "pop a block number: fail, the unit has no block of that number (a computed GOTO)")         \
  X(Service, "h", 0, 0, "run host service h: its operands and stack effect are the catalogue's")

// An X-macro list, then Count: clang-format would indent Count as a continuation.
// clang-format off
enum class Op : uint8_t {
#define NCC_OP_ENUM(name, format, pop, push, doc) name,
  NCC_OPCODES(NCC_OP_ENUM)
#undef NCC_OP_ENUM
  Count
};
// clang-format on

struct OpInfo {
  std::string_view name;
  std::string_view format;
  uint8_t pop;
  uint8_t push;
  std::string_view doc;
};

// (Inline, as the verifier reads it for every instruction.)
inline constexpr OpInfo kOpInfo[] = {
#define NCC_OP_INFO(name, format, pop, push, doc) {#name, format, pop, push, doc},
    NCC_OPCODES(NCC_OP_INFO)
#undef NCC_OP_INFO
};
constexpr const OpInfo& op_info(Op op) { return kOpInfo[static_cast<size_t>(op)]; }
// The kind of an operand letter (Operand::Count: no kind has it).
constexpr Operand operand_kind(char letter) {
#define NCC_OPERAND_KIND(kind, l, size, doc) \
  if (letter == l) return Operand::kind;
  NCC_OPERANDS(NCC_OPERAND_KIND)
#undef NCC_OPERAND_KIND
  return Operand::Count;
}
// Bytes an operand of this letter takes.
constexpr int operand_size(char letter) {
#define NCC_OPERAND_SIZE(kind, l, size, doc) \
  if (letter == l) return size;
  NCC_OPERANDS(NCC_OPERAND_SIZE)
#undef NCC_OPERAND_SIZE
  return 0;
}
constexpr bool known_operands(std::string_view format) {
  for (char f : format)
    if (operand_kind(f) == Operand::Count) return false;
  return true;
}
#define NCC_OP_FORMAT_CHECK(name, format, pop, push, doc) \
  static_assert(known_operands(format), #name "'s format has a letter of no operand kind");
NCC_OPCODES(NCC_OP_FORMAT_CHECK)
#undef NCC_OP_FORMAT_CHECK
#define SERVICE(name, printed, format, pop, push, device, doc) \
  static_assert(known_operands(format), "service " #name "'s format has a letter of no operand kind");
#include "contract/services.def"
#undef SERVICE
constexpr int operand_bytes(std::string_view format) {
  int size = 0;
  for (char f : format) size += operand_size(f);
  return size;
}
// The size of an instruction with opcode `op` (inline: the VM steps by it); a SERVICE's
// without the operands of its service, which follow.
inline constexpr uint8_t kInstructionSizes[] = {
#define NCC_OP_SIZE(name, format, pop, push, doc) static_cast<uint8_t>(1 + operand_bytes(format)),
    NCC_OPCODES(NCC_OP_SIZE)
#undef NCC_OP_SIZE
};
constexpr int instruction_size(Op op) { return kInstructionSizes[static_cast<size_t>(op)]; }
// The bytes of each service's own operands.
inline constexpr uint8_t kServiceOperandSizes[] = {
#define SERVICE(name, printed, format, pop, push, device, doc) static_cast<uint8_t>(operand_bytes(format)),
#include "contract/services.def"
#undef SERVICE
};
constexpr int service_operand_size(Service s) { return kServiceOperandSizes[static_cast<size_t>(s)]; }
// The size of the whole instruction at `at`, whose SERVICE (if it is one) names a service.
inline int instruction_size(const uint8_t* at) {
  const Op op = static_cast<Op>(at[0]);
  const int size = instruction_size(op);
  return op == Op::Service ? size + service_operand_size(static_cast<Service>(at[1])) : size;
}
// A SERVICE instruction as its service makes it: the service's name, the format "h"
// and its own operands, its stack effect.
inline constexpr OpInfo kServiceOpInfo[] = {
#define SERVICE(name, printed, format, pop, push, device, doc) {printed, "h" format, pop, push, doc},
#include "contract/services.def"
#undef SERVICE
};
static_assert(op_info(Op::Service).format == "h");
constexpr const OpInfo& service_op_info(Service s) { return kServiceOpInfo[static_cast<size_t>(s)]; }
// What the instruction at `at` is to the verifier: its opcode's info, or its service's.
inline const OpInfo& instruction_info(const uint8_t* at) {
  const Op op = static_cast<Op>(at[0]);
  return op == Op::Service ? service_op_info(static_cast<Service>(at[1])) : op_info(op);
}
// An operand of `size` bytes at `p`, little-endian.
inline uint32_t read_operand(const uint8_t* p, int size) {
  uint32_t v = 0;
  for (int i = 0; i < size; ++i) v |= uint32_t(p[i]) << (8 * i);
  return v;
}

// Powers of ten for WORDDEC: m / kPowersOfTen[p] is the correctly rounded value of
// the decimal, the same double as reading its text.
inline constexpr double kPowersOfTen[10] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr uint32_t kMaxDecimalPlaces = 9;
// The number the operands `p m` stand for (the lowering, the VM and the disassembler
// all read it here, so a constant comes back bit for bit).
inline double decimal(uint32_t places, int32_t digits) { return places == 0 ? digits : digits / kPowersOfTen[places]; }
inline double decimal_at(const uint8_t* p) { return decimal(p[0], static_cast<int32_t>(read_operand(p + 1, 4))); }

}  // namespace ncc::vm
