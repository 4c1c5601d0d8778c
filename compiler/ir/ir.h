// The common intermediate representation of every dialect.
//
// A Program is a list of Units (programs on a medium, subprograms, macros). A Unit is
// a list of source Blocks. A Block keeps its source range and its original words
// (address, text, value) and lists its semantic statements in execution order: the
// machine action (its G/M codes and parameter words), assignments, jumps, repeat
// loops, calls, returns and calls of the controller's services. Expressions live in
// one arena per Program. The dialect's code table (Program::semantics) says what each
// G/M code means to the runtime. `ncc ir` prints all of it as stable text (ir_print.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "contract/builtins.h"
#include "contract/program_semantics.h"
#include "contract/services.h"
#include "contract/system_vars.h"
#include "contract/variables.h"
#include "support/numbers.h"
#include "support/source.h"

namespace ncc::ir {

using ExprId = uint32_t;
constexpr ExprId kNoExpr = UINT32_MAX;

enum class ExprOp : uint8_t {
  Number,  // number
  Var,     // space[index a]
  Neg,
  Not,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
  Pow,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  And,
  Or,
  Xor,
  Call,          // builtin(a[, b])
  Mem,           // the value of `format` at index a of memory `space`
  Sys,           // system variable `sys` (SysRef::packed)
  Text,          // `count` bytes at byte a of memory `space`: not a number
  String,        // Program::texts[text]: not a number
  TextEq,        // 1 if Text a holds the bytes of Text or String b
  Check,         // a, which must meet semantics.value_rules[rule] (reported at word `slot`)
  ZeroIfVacant,  // a, or 0 if it is vacant (Macro B: a vacant operand of arithmetic)
};

struct Expr {
  ExprOp op = ExprOp::Number;
  Builtin builtin = Builtin::Sin;  // Call
  uint16_t space = 0;              // Var, Mem, Text: index into Program::spaces
  double number = 0;               // Number
  ExprId a = kNoExpr;
  ExprId b = kNoExpr;
  SourceRange range;
  MemFormat format = MemFormat::Byte;  // Mem
  uint16_t sys = 0;                    // Sys
  uint32_t text = 0;                   // String: index into Program::texts
  uint8_t count = 0;                   // Text: bytes
  uint8_t slot = 0;                    // Check
  uint8_t rule = 0;                    // Check
};

enum class WordKind : uint8_t {
  Parameter,    // a value the machine action reads: X, F, S...
  Code,         // a G or M code: `code` indexes Program::semantics.codes
  BlockNumber,  // N or ':'
  Ignored,      // kept for printing only (a word the checks rejected)
  Control,      // read by a statement, not by the machine (pp L and Q of a call or jump)
  Argument,     // a value a macro call gives the macro (Macro B G65 A..Z: I J K may repeat)
};

// A Code word whose code is found at run time from its value (NC-110 `GE1`).
constexpr int32_t kDynamicCode = -2;

// A word's address as written, held in the word itself: a letter ("X", "N"), a
// letter and a mark ("R'"), an operand slot ("#12") or an NC-110 three-letter code
// ("RPT"): at most kMax characters (the NC-110 settings take codes of three letters;
// a unit test checks the slot names).
class Address {
 public:
  static constexpr size_t kMax = 7;
  Address() = default;
  Address(std::string_view s) : size_(static_cast<uint8_t>(std::min(s.size(), kMax))) { s.copy(chars_, size_); }
  Address(const char* s) : Address(std::string_view(s)) {}
  Address(const std::string& s) : Address(std::string_view(s)) {}
  operator std::string_view() const { return {chars_, size_}; }
  std::string str() const { return std::string(std::string_view(*this)); }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  char operator[](size_t i) const { return chars_[i]; }
  Address& operator+=(std::string_view s) { return *this = Address(str() + std::string(s)); }
  friend bool operator==(const Address& a, std::string_view b) { return std::string_view(a) == b; }
  friend bool operator==(const Address& a, const char* b) { return std::string_view(a) == b; }
  friend std::string operator+(const Address& a, std::string_view b) { return a.str() + std::string(b); }
  friend std::string operator+(const Address& a, const std::string& b) { return a.str() + b; }
  friend std::string operator+(const Address& a, const char* b) { return a.str() + b; }

 private:
  char chars_[kMax] = {};
  uint8_t size_ = 0;
};

// (Fields ordered to pack: a CAM block holds several words, a program millions.)
struct Word {
  WordKind kind = WordKind::Parameter;
  uint8_t slot = 0;
  bool optional = false;  // after a mid-block '/': dropped when block skip is on
  bool derived = false;   // made by the reader from another word (NC-110 G72's result slots, GOST's T offset)
  Address address;        // as written: "X", "G", ":"
  ExprId value = kNoExpr;
  int32_t code = -1;
  SourceRange range;
  std::string text;  // the value as written: "-10.5", "01"
};

enum class StmtKind : uint8_t {
  Comment,      // operator text shown when the block runs (`label`)
  Machine,      // run the block's codes and parameter words on the runtime
  Assign,       // target := value
  Jump,         // go to `label` (if `cond` is true, when given); no label: to the block numbered `value`
  RepeatBegin,  // repeat the statements up to the matching RepeatEnd `count` times
  RepeatEnd,
  Call,  // call unit/file `label` (a block of its unit: "unit/label"), `value` times, with `args`
  Return,
  CallRange,  // run the blocks from label `label` to label `end_label`, then go on
  Display,    // show `items` to the operator, one after the other
  // Call the controller's service `service` (contract/services.def), named by the
  // front end as the statement's words select it (NC-110 ASSET, INP, SCR, DEF, OUT,
  // EXE, REL, WAI, SND). Lowering turns it into that one Service instruction, except
  // where one statement is several (docs/ir.md, Services): asset.define binds its
  // variables first, an input.* stores the answer, screen.show shows each field.
  // Operands: asset.*: `items` in stack order (define: the structure, then the
  // variables), `label` the file. input.*: `target` entered, items[0] the field whose
  // text is the prompt (0: the prompt is `label`), items[1] a field to show the answer.
  // screen.define_*: items field, row, column, initial value[, format], `label` the
  // attribute (R, A179) or "". screen.show: items the fields (-n: inverse);
  // screen.show_value/_text/_mem: items field, value. process.*: `value` the process
  // (wait_until: the comparison of a memory), `label` the program (start) or the
  // condition as written (wait_until).
  Service,
};

// One item of a Display: a value shown as its type shows it, a String or a Text.
struct DisplayItem {
  ExprId value = kNoExpr;
  VarType type = VarType::LongReal;
};

// A value a call gives a local variable of the called code (Macro B G65 A..Z).
struct CallArg {
  uint16_t space = 0;
  uint32_t index = 0;
  ExprId value = kNoExpr;
};

// (Fields ordered to pack: every block holds at least one.)
struct Stmt {
  Stmt() = default;
  Stmt(StmtKind k, SourceRange r) : kind(k), range(r) {}

  StmtKind kind = StmtKind::Machine;
  bool optional = false;                 // Comment after a mid-block '/': dropped when block skip is on
  bool shares_locals = false;            // Call: the called code keeps the caller's locals (Macro B M98)
  Service service = Service::AssetBind;  // Service
  SourceRange range;
  ExprId target = kNoExpr;         // Assign: a Var expression
  ExprId value = kNoExpr;          // Assign value; RepeatBegin count; Call count (none: once)
  ExprId cond = kNoExpr;           // Jump condition; any other statement runs only if it is true
  SourceRange end_range;           // CallRange: where end_label is written
  double limit = 0;                // RepeatBegin: the largest count allowed (0: no limit of the dialect)
  std::string label;               // Jump target label; Call target; Comment text
  std::string end_label;           // CallRange
  std::vector<DisplayItem> items;  // Display; Service
  std::vector<CallArg> args;       // Call
};

struct Block {
  SourceRange range;
  std::optional<uint32_t> number;  // N / ':' value
  bool main_block = false;         // ':' (GOST 20999 §2.6)
  bool skippable = false;          // '/' before the block: skipped when block skip is on
  bool has_errors = false;
  bool unread = false;        // refused whole, beyond a limit: its label too is unknown
  char sync = 0;              // NC-110 '#': wait for the motion before; '&': do not
  bool waits_motion = false;  // evaluated once the motion before it has ended ('#', NC-110 SA/SK blocks)
  std::string label;
  std::vector<Word> words;
  std::vector<std::string> comments;
  std::vector<Stmt> stmts;
};

// A Process unit is a program another process starts (NC-110 EXE): not run in the
// order of the medium.
enum class UnitKind : uint8_t { Program, Subprogram, Macro, Process };

struct Unit {
  UnitKind kind = UnitKind::Program;
  std::string name;   // "%0001", "%" for a program without number
  std::string title;  // the comment of the program-start line
  SourceRange range;
  std::vector<Block> blocks;
  uint32_t streamed = 0;  // blocks before `blocks`, compiled and dropped while reading (BlockSink)
  // Of those, the ones with a label, in order: what later jumps, calls and checks
  // need of them. A streamed label is N and the block's number (12 bytes less a
  // block than the text: CAM output numbers every block).
  struct StreamedLabel {
    uint32_t number;
    SourceRange range;
    std::string label() const { return "N" + std::to_string(number); }
  };
  std::vector<StreamedLabel> streamed_labels;
  // Of them, the ones the blocks held name (indices in streamed_labels, in order).
  std::vector<size_t> named_streamed_labels() const;
  bool ends_information = false;  // terminated by end of information (M30)
  uint8_t processes = 0;  // a Process unit started in process n when the run starts: bit n-1 (none: by EXE only)
};

struct Program {
  std::string dialect;
  std::vector<uint32_t> files;  // SourceManager indices of the files read
  ProgramSemantics semantics;
  std::vector<VarSpace> spaces;
  std::vector<Expr> exprs;
  std::vector<std::string> texts;  // string constants
  std::vector<Unit> units;

  ExprId add(Expr e) {
    exprs.push_back(e);
    return static_cast<ExprId>(exprs.size() - 1);
  }
  ExprId number(double v, SourceRange range) {
    return add({ExprOp::Number, Builtin::Sin, 0, v, kNoExpr, kNoExpr, range});
  }
  bool is_constant(ExprId id) const { return id != kNoExpr && exprs[id].op == ExprOp::Number; }
};

// The table key (code_key) of a code whose value is written (G01, G54.1); -1, which no
// code table holds, for any other value.
inline int code_number(const Program& program, ExprId value) {
  return code_key(program.exprs[value].number).value_or(-1);
}

std::string print(const Program& program, const SourceManager& sources);
std::string print_expr(const Program& program, ExprId id);

}  // namespace ncc::ir

template <>
struct fmt::formatter<ncc::ir::Address> : fmt::formatter<std::string_view> {
  auto format(const ncc::ir::Address& a, format_context& ctx) const {
    return fmt::formatter<std::string_view>::format(std::string_view(a), ctx);
  }
};
