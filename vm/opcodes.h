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
// ASSET files (NC-110 chapter 5, docs/asset.md): a record structure is built up by
// ASSETBIND* and defined by ASSETDEFINE; the I/O instructions (open, read, write,
// close, create, delete) set IOSTA and stop the run on an error while ERR is 0.
//
// Processes (NC-110 chapter 4): PROCSTART, PROCWAIT, PROCWAITUNTIL and PROCSIGNAL may
// have to wait for another process. Then the instruction is left to run again, its
// operands back on the stack, and the VM returns Blocked to the scheduler that runs
// the processes (vm/processes.h).
//
// Frames: CALLENTRY calls an entry point (again, while its count lasts), RETURN comes
// back; the local variables start afresh in every call (ARGs before it give some of
// them values), except in a CALLSHARED call (Macro B M98). CALLRANGE runs the code
// from one place to a RANGEEND (NC-110 EPP) and comes back after it; a range does
// not run inside another, and a jump out of it ends it.
#pragma once

#include <cstdint>
#include <string_view>

namespace ncc::vm {

// The operand kinds: name, letter, bytes, what the value is (and the range the verifier
// allows it).
#define NCC_OPERANDS(X)                                                                          \
  X(Number, 'k', 4, "index into the number constants")                                           \
  X(String, 's', 4, "index into the strings (an ASSET statement's: a file name, docs/asset.md)") \
  X(Code, 'c', 2, "index into the program's codes")                                              \
  X(Slot, 'w', 1, "word slot (contract/word_slots.h)")                                           \
  X(Target, 'j', 4, "code offset of an instruction")                                             \
  X(Entry, 'e', 2, "index into the entry points (ProcStart: a process entry; others: not one)")  \
  X(Space, 'v', 1, "variable space (Load, Store, Arg, AssetBind: numbered; others: a memory)")   \
  X(Index, 'i', 4, "variable index, below the size of the space before it")                      \
  X(Builtin, 'b', 1, "builtin function of the instruction's arity (contract/builtins.h)")        \
  X(Format, 'f', 1, "memory format (contract/variables.h)")                                      \
  X(Bytes, 'n', 1, "a count of bytes, 1..255")                                                   \
  X(Relation, 'q', 1, "a comparison: 1 =, 2 <, 3 >, 4 not =")                                    \
  X(Type, 't', 1, "value type a value is shown as (contract/variables.h), not Unavailable")      \
  X(SysVar, 'y', 2, "system variable: its number << 8 | its index (contract/system_vars.def)")   \
  X(LoopDepth, 'd', 1, "a repeat-loop depth (0: outside every loop)")                            \
  X(Rule, 'r', 1, "index into the program's value rules (ProgramSemantics::value_rules)")        \
  X(Places, 'p', 1, "decimal places 0..9, then")                                                 \
  X(Digits, 'm', 4, "the digits, an i32: the number m / 10^p")

// An X-macro list, then Count: clang-format would indent Count as a continuation.
// clang-format off
enum class Operand : uint8_t {
#define NCC_OPERAND_ENUM(kind, letter, size, doc) kind,
  NCC_OPERANDS(NCC_OPERAND_ENUM)
#undef NCC_OPERAND_ENUM
  Count
};
// clang-format on

#define NCC_OPCODES(X)                                                                                              \
  X(Nop, "", 0, 0, "do nothing")                                                                                    \
  X(Const, "k", 0, 1, "push numbers[k]")                                                                            \
  X(ConstDec, "pm", 0, 1, "push m / 10^p (a constant as written)")                                                  \
  X(Load, "vi", 0, 1, "push variable v[i]")                                                                         \
  X(LoadX, "v", 1, 1, "pop an index; push variable v[index]")                                                       \
  X(Store, "vi", 1, 0, "pop a value into variable v[i]")                                                            \
  X(StoreX, "v", 2, 0, "pop a value, then an index; store the value into v[index]")                                 \
  X(Neg, "", 1, 1, "negate the top")                                                                                \
  X(Not, "", 1, 1, "1 if the top is 0, else 0")                                                                     \
  X(Add, "", 2, 1, "a + b")                                                                                         \
  X(Sub, "", 2, 1, "a - b")                                                                                         \
  X(Mul, "", 2, 1, "a * b")                                                                                         \
  X(Div, "", 2, 1, "a / b; division by zero is a run-time error")                                                   \
  X(Mod, "", 2, 1, "a mod b (sign of a); b = 0 is a run-time error")                                                \
  X(Pow, "", 2, 1, "a to the power b")                                                                              \
  X(Eq, "", 2, 1, "1 if a == b")                                                                                    \
  X(Ne, "", 2, 1, "1 if a != b")                                                                                    \
  X(Lt, "", 2, 1, "1 if a < b")                                                                                     \
  X(Le, "", 2, 1, "1 if a <= b")                                                                                    \
  X(Gt, "", 2, 1, "1 if a > b")                                                                                     \
  X(Ge, "", 2, 1, "1 if a >= b")                                                                                    \
  X(And, "", 2, 1, "1 if a and b are not 0")                                                                        \
  X(Or, "", 2, 1, "1 if a or b is not 0")                                                                           \
  X(Xor, "", 2, 1, "1 if exactly one of a, b is not 0")                                                             \
  X(Call1, "b", 1, 1, "apply the one-argument builtin b")                                                           \
  X(Call2, "b", 2, 1, "apply the two-argument builtin b to a, b")                                                   \
  X(Jump, "j", 0, 0, "go to j")                                                                                     \
  X(JumpIfNot, "j", 1, 0, "pop; go to j if it is 0")                                                                \
  X(JumpIf, "j", 1, 0, "pop; go to j if it is not 0")                                                               \
  X(JumpSkip, "j", 0, 0, "go to j if the block-skip switch of the runtime is on")                                   \
  X(Step, "", 0, 0, "count one executed block against --max-steps")                                                 \
  X(Sync, "", 0, 0, "the block is evaluated once the motion before it has ended (NC-110 '#')")                      \
  X(Code, "c", 0, 0, "add G/M code c to the pending block")                                                         \
  X(CodeOf, "w", 1, 0, "pop a number; add the code of letter slot w with that number")                              \
  X(Word, "wk", 0, 0, "set word w of the pending block to numbers[k]")                                              \
  X(WordDec, "wpm", 0, 0, "set word w of the pending block to m / 10^p (a constant as written)")                    \
  X(WordPop, "w", 1, 0, "pop the value of word w of the pending block")                                             \
  X(Exec, "", 0, 0, "run the pending block on the motion runtime, then clear it")                                   \
  X(Comment, "s", 0, 0, "show strings[s] to the operator")                                                          \
  X(Repeat, "jk", 1, 0, "pop a count 0..numbers[k]; open a repeat loop, or go to j if it is 0")                     \
  X(EndRepeat, "j", 0, 0, "count down the innermost repeat loop; go to j while it runs")                            \
  X(Unloop, "d", 0, 0, "the next jump lands at repeat-loop depth d of its code: close deeper loops")                \
  X(CallEntry, "e", 1, 0, "pop a count 1..9999; call entry point e that many times, one after the other")           \
  X(CallRange, "jjd", 0, 0, "run the code from j1 (at loop depth d) to the RANGEEND at j2, then come back")         \
  X(RangeEnd, "", 0, 0, "the end of a range: come back if the innermost frame runs it")                             \
  X(Return, "", 0, 0, "return from a call")                                                                         \
  X(End, "", 0, 0, "end of the program unit")                                                                       \
  X(LoadMem, "vf", 1, 1, "pop an index; push the value of format f there in memory v")                              \
  X(StoreMem, "vf", 2, 0, "pop a value, then an index; store it in format f in memory v")                           \
  X(StoreText, "vs", 1, 0, "pop a byte index; write the bytes of strings[s] there in memory v")                     \
  X(CopyText, "vvn", 2, 0, "pop a source, then a target byte index; copy n bytes v2 -> v1")                         \
  X(EqText, "vs", 1, 1, "pop a byte index; 1 if memory v holds the bytes of strings[s] there")                      \
  X(EqMem, "vvn", 2, 1, "pop two byte indices; 1 if their n bytes (memories v1, v2) are equal")                     \
  X(GetSys, "y", 0, 1, "push system variable y of the runtime")                                                     \
  X(SetSys, "y", 1, 0, "pop a value into system variable y of the runtime")                                         \
  X(Show, "s", 0, 0, "append strings[s] to the pending message")                                                    \
  X(ShowValue, "t", 1, 0, "pop a value; append it to the pending message as type t shows")                          \
  X(ShowText, "vn", 1, 0, "pop a byte index; append n bytes of memory v to the pending message")                    \
  X(Message, "", 0, 0, "show the pending message to the operator, then clear it")                                   \
  X(Check, "wr", 1, 1, "fail at word w unless the top meets value rule r (a parameter's value)")                    \
  X(ZeroIfVacant, "", 1, 1, "a vacant top (an unset Macro B variable) reads as 0")                                  \
  X(Arg, "vi", 1, 0, "pop a value into local variable v[i] of the next CALLENTRY's frame")                          \
  X(CallShared, "e", 1, 0, "pop a count 1..9999; call entry point e that many times, keeping the caller's locals")  \
  X(NoBlock, "", 1, 0, "pop a block number: fail, the unit has no block of that number (a computed GOTO)")          \
  X(AssetBind, "vi", 0, 0, "add variable v[i] to the record structure being defined (NC-110 DER)")                  \
  X(AssetBindMem, "vf", 1, 0, "pop an index; add memory v's value of format f there to the structure")              \
  X(AssetBindText, "vn", 1, 0, "pop a byte index; add memory v's n bytes from there to the structure")              \
  X(AssetDefine, "", 1, 0, "pop a structure number: the variables added are its fields, in order")                  \
  X(AssetOpen, "s", 1, 0, "pop a channel; open file strings[s] on it to read")                                      \
  X(AssetOpenWrite, "s", 1, 0, "pop a channel; open file strings[s] on it to read and write")                       \
  X(AssetRead, "", 2, 0, "pop a structure, then a channel; read the next record into its variables")                \
  X(AssetReadAt, "", 3, 0, "pop a record, a structure, a channel; read that record into its variables")             \
  X(AssetWrite, "", 2, 0, "pop a structure, then a channel; write its variables into the next record")              \
  X(AssetWriteAt, "", 3, 0, "pop a record, a structure, a channel; write its variables into that record")           \
  X(AssetClose, "", 1, 0, "pop a channel; close it")                                                                \
  X(AssetCloseAll, "", 0, 0, "close every channel")                                                                 \
  X(AssetCreate, "s", 2, 0, "pop a record count, then a structure; create file strings[s] of its layout")           \
  X(AssetDelete, "s", 0, 0, "delete file strings[s]")                                                               \
  X(Input, "s", 1, 1, "pop the value offered after prompt strings[s]; push the operator's answer (NC-110 INP)")     \
  X(InputField, "", 2, 1, "pop the value offered, then a screen field whose text is the prompt; push the answer")   \
  X(InputText, "vns", 1, 0,                                                                                         \
    "pop a byte index: the operator answers the n bytes of memory v there after prompt strings[s]")                 \
  X(InputFieldText, "vn", 2, 0, "pop a byte index, then a screen field whose text is the prompt; the same")         \
  X(ScreenOn, "", 0, 0, "the user screen on, clear, without fields (NC-110 SCR)")                                   \
  X(ScreenOff, "", 0, 0, "the user screen off")                                                                     \
  X(ScreenDefineText, "s", 5, 0, "pop attribute, format, column, row, field; define it with text strings[s] (DEF)") \
  X(ScreenDefineValue, "", 6, 0, "pop a value, attribute, format, column, row, field; define it with the value")    \
  X(ScreenShow, "", 1, 0, "pop a field; show it (negative: inverse) (OUT)")                                         \
  X(ScreenShowAll, "", 0, 0, "show every defined field not shown yet")                                              \
  X(ScreenShowValue, "", 2, 0, "pop a value, then a field; show the field with that value")                         \
  X(ScreenShowText, "s", 1, 0, "pop a field; show it with text strings[s]")                                         \
  X(ScreenDefineMem, "vn", 6, 0,                                                                                    \
    "pop a byte index, attribute, format, column, row, field; define it with n bytes of memory v")                  \
  X(ScreenShowMem, "vn", 2, 0, "pop a byte index, then a field; show the field with n bytes of memory v there")     \
  X(ProcStart, "e", 1, 0, "pop a process; start process entry e in it once it is free (NC-110 EXE)")                \
  X(ProcRelease, "", 0, 0, "end the program: its process is free (NC-110 REL)")                                     \
  X(ProcWait, "", 1, 0, "pop a process; wait for a restart from it (NC-110 WAI)")                                   \
  X(ProcWaitUntil, "vfqs", 2, 0,                                                                                    \
    "pop a value, an index; wait until memory v (format f) there relates to it by q; s: as written")                \
  X(ProcSignal, "", 1, 0, "pop a process; restart it once it waits for this one (NC-110 SND)")

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

const OpInfo& op_info(Op op);
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
// The size of a whole instruction with opcode `op` (inline: the VM steps by it).
constexpr int operand_bytes(std::string_view format) {
  int size = 0;
  for (char f : format) size += operand_size(f);
  return size;
}
inline constexpr uint8_t kInstructionSizes[] = {
#define NCC_OP_SIZE(name, format, pop, push, doc) static_cast<uint8_t>(1 + operand_bytes(format)),
    NCC_OPCODES(NCC_OP_SIZE)
#undef NCC_OP_SIZE
};
constexpr int instruction_size(Op op) { return kInstructionSizes[static_cast<size_t>(op)]; }
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
