// The NC-110 reader: one file, block by block, into an IR unit. Each line is told
// apart first (§2.5), then lexed in the mode of its block type and parsed by the
// ANTLR grammar (grammar/Nc110*.g4); the visitor code here turns the parse tree
// into IR and reports what the grammar cannot say (reader.cpp: leading fields and
// ISO blocks; expressions.cpp: assignments; codes.cpp: three-letter codes; gtl.cpp:
// GTL definitions).
#pragma once

#include <antlr4-runtime.h>

#include "Nc110Lexer.h"
#include "Nc110Parser.h"
#include "frontend/frontend.h"
#include "frontend/plain_words.h"
#include "ir/ir.h"
#include "settings.h"

namespace ncc::nc110 {

// A CLS of the file: the program it calls, for the front end to find and read.
struct CallSite {
  std::string name;    // P800
  std::string device;  // MP2, or the default
  std::string entry;   // the unit's name: MP2/P800
  SourceRange range;
  size_t unit = 0, block = 0;                    // where the call stands
  ir::UnitKind kind = ir::UnitKind::Subprogram;  // Process: a program EXE starts
};

using ncc_nc110::Nc110Lexer;
using ncc_nc110::Nc110Parser;

// The dialect's name of each built-in function (SQR for the square root), by Builtin.
std::vector<std::string> function_names();

// The letters of GTL elements: points, lines, circles, origins (§2.11).
inline constexpr std::string_view kGtlElements = "oplc";

class Reader {
 public:
  // `sink` takes each block as it is finished (see BlockSink).
  Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file, Diagnostics& diags,
         bool fast_path, BlockSink* sink = nullptr);
  ~Reader();

  // Reads the whole file into `unit`.
  void run(ir::Unit& unit);
  const std::vector<CallSite>& calls() const { return calls_; }

 private:
  enum class Kind { Iso, Assign, Code, Gtl };
  Kind kind_ = Kind::Iso;  // of the block being read

  // Lines and tokens.
  void read_line(std::string_view line, uint32_t line_no);
  void keep_block();  // adds the block read to the unit, unless it is empty
  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  SourceRange range(antlr4::ParserRuleContext* ctx) const { return range(ctx->getStart(), ctx->getStop()); }
  SourceRange range(antlr4::tree::TerminalNode* t) const { return range(t->getSymbol(), t->getSymbol()); }
  uint32_t byte_col(size_t code_point) const;
  std::string text(antlr4::Token* first, antlr4::Token* last) const;  // the source between them

  // reader.cpp: the leading fields and ISO blocks.
  void leading(Nc110Parser::LeadingContext* ctx, bool has_body);
  void iso_block(Nc110Parser::IsoBlockContext* ctx);
  [[nodiscard]] bool scan_plain(std::string_view line);  // the fast path: an ISO block of address words only
  void finish_iso_block();
  void block_number(std::string_view digits, SourceRange r);
  // An address word's value as written: `sign` 0, '+' or '-'; a NUMBER or an EREF.
  struct WordValue {
    char sign = 0;
    std::string_view number, eref;
    std::string written;  // the source from the sign to the end: "- 10.5"
  };
  void address_word(Nc110Parser::AddressWordContext* ctx);
  void address_word(char letter, const WordValue* v, SourceRange r);
  void tool_word(Nc110Parser::ToolWordContext* ctx);
  void result_word(Nc110Parser::ResultWordContext* ctx);
  void check_iso_block();
  int32_t code_index(char letter, int number);
  // A constant of `letter`'s range and format; nullopt (reported) if it is not one.
  [[nodiscard]] std::optional<double> constant(char letter, std::string_view written, bool negative, SourceRange r,
                                               const std::string& shown);
  void add_word(char letter, int slot, ir::ExprId value, std::string text, SourceRange r,
                ir::WordKind kind = ir::WordKind::Parameter, int32_t code = -1);

  // expressions.cpp: assignments, expressions and references.
  void assign_block(Nc110Parser::AssignBlockContext* ctx);
  ir::ExprId expr(Nc110Parser::ExprContext* ctx);
  ir::ExprId term(Nc110Parser::TermContext* ctx);
  ir::ExprId factor(Nc110Parser::FactorContext* ctx);
  ir::ExprId primary(Nc110Parser::PrimaryContext* ctx);

  // An E parameter: `E 35` -> 35, checked against the machine's count.
  [[nodiscard]] std::optional<uint32_t> parameter(std::string_view text, SourceRange r);
  ir::ExprId parameter_expr(uint32_t index, SourceRange r);
  // Reports unless E`index` is of one of `classes`; `what` names the place.
  [[nodiscard]] bool check_class(uint32_t index, const std::vector<std::string>& classes, SourceRange r,
                                 const std::string& what);
  // SA12, SYVAR1.2CH: the memory, its format (or n characters) and index.
  struct MemoryRef {
    const Memory* memory = nullptr;
    MemFormat format = MemFormat::Byte;
    uint32_t chars = 0;  // a text of this many characters (CH)
    uint32_t index = 0;
    std::string text;
  };
  [[nodiscard]] std::optional<MemoryRef> memory_ref(std::string_view text, SourceRange r);
  ir::ExprId memory_expr(const MemoryRef& ref, SourceRange r);
  // A system variable by name and number, to read or (writing) to write.
  // The number after a system variable's name (TIM1), which must be whole.
  [[nodiscard]] bool system_number(antlr4::tree::TerminalNode* n, const std::string& name, SourceRange r,
                                   std::optional<uint32_t>& out);
  [[nodiscard]] std::optional<SysRef> system_ref(const std::string& name, std::optional<uint32_t> number, SourceRange r,
                                                 bool writing, const SystemName** entry = nullptr);
  ir::ExprId system_expr(SysRef ref, SourceRange r);
  ir::ExprId string_expr(std::string text, SourceRange r);
  // The value type DIS shows an E parameter with.
  VarType parameter_type(uint32_t index) const { return s_.class_of(index).type; }

  // codes.cpp: three-letter codes.
  void code_block(Nc110Parser::TlcBlockContext* ctx);
  void gtl_block(Nc110Parser::GtlBlockContext* ctx);
  [[nodiscard]] std::optional<ir::ExprId> gtl_value(char letter, bool minus, Nc110Parser::WordValueContext* v,
                                                    SourceRange r);
  void code_operands(Nc110Parser::TlcBlockContext* ctx, const CodeSignature& sig, SourceRange code_range);
  struct Piece;
  struct Operand;
  // GTL geometry (§2.11) is later work: an element (`c1`) or a definition (`c1=...`)
  // is reported as not supported.
  // Reports a second instruction starting at byte `at` of the line, if there is one.
  [[nodiscard]] bool second_instruction(size_t at);
  // A Cyrillic letter where a Latin one is read: NC1027 naming its Latin twin, if any.
  void report_cyrillic(const SourceRange& range, const std::string& letter);
  [[nodiscard]] std::optional<Operand> operand(const std::vector<Piece>& pieces, OperandKind kind,
                                               const std::string& code);
  void code_action(const CodeSignature& sig, const std::vector<Operand>& operands, SourceRange code_range);
  // Every value of RQU's increments is an E parameter a measuring cycle above stores.
  bool measured(const std::vector<Operand>& operands) const;
  // A code that needs '#' without it: reported once a code, at the end of the file,
  // with the count of the others.
  void unsynced(const std::string& code, SourceRange at, const char* why);
  struct Unsynced {
    std::string code;
    SourceRange at;
    const char* why;
    size_t more;
  };
  std::vector<Unsynced> unsynced_;
  [[nodiscard]] bool virtual_operands(const CodeSignature& sig, const std::vector<Operand>& operands,
                                      SourceRange code_range);  // UAV's, by mode
  // The three-letter code a line starts with before the comma at `comma`, typed as at
  // the keyboard ("DPT, 10, 12, 1000"), or "".
  std::string keyboard_form(size_t comma) const;

  const Settings& s_;
  ir::Program& program_;
  const SourceFile& source_;
  uint32_t file_;
  Diagnostics& diags_;

  antlr4::ANTLRInputStream input_;
  Nc110Lexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  Nc110Parser parser_{&tokens_};
  class Listener;
  std::unique_ptr<Listener> listener_;

  std::string_view line_;
  uint32_t line_no_ = 0;
  bool fast_path_;
  BlockSink* sink_;
  PlainBlock plain_;
  std::string decoded_;            // the line as ANTLR reads it
  std::vector<uint32_t> byte_of_;  // the byte offset of each code point of the line, and the end
  ir::Unit* unit_ = nullptr;
  ir::Block block_;
  std::string last_operand_;  // the last word of the block that is not a G word, as written
  std::vector<CallSite> calls_;
  std::vector<bool> measured_;  // E parameters G72-G74 blocks above store their results in
};

}  // namespace ncc::nc110
