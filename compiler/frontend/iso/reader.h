// Reads one iso file: cuts the text into blocks (';', the end of a line, the braces
// of a multi-line IF), parses each with the ANTLR grammar, and builds the program
// structure (the main program, O subprograms and macros, M97 blocks after M30) and
// the Macro B control flow (GOTO, IF, WHILE/DO/END) into IR units.
#pragma once

#include <antlr4-runtime.h>

#include <map>
#include <optional>

#include "IsoLexer.h"
#include "IsoParser.h"
#include "frontend/block_errors.h"
#include "frontend/frontend.h"
#include "frontend/plain_words.h"
#include "ir/ir.h"
#include "settings.h"

namespace ncc::iso {

using ncc_iso::IsoLexer;
using ncc_iso::IsoParser;

// A call of an O program (M98, G65), for the front end to find it.
struct ProgramCall {
  std::string name;  // "O1002"
  SourceRange range;
  size_t unit = 0, block = 0;
};

class Reader {
 public:
  // `called`: the file of a called program (its blocks form one subprogram named so).
  // `sink` takes the main program's blocks as they are finished (see BlockSink).
  Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file, Diagnostics& diags,
         uint16_t space, std::optional<std::string> called, bool fast_path, BlockSink* sink = nullptr);
  ~Reader();

  // Appends the file's units to the program.
  void run();
  const std::vector<ProgramCall>& calls() const { return calls_; }

  // "O1002": the name of program 1002.
  static std::string program_name(uint32_t number);

 private:
  void program_range(SourceRange r, const std::string& written, const std::string& what);
  struct Piece;
  struct Loop;
  struct Branch;

  void cut();
  bool semicolon_comment(std::string_view line, size_t at, uint32_t line_no);
  bool is_block(std::string_view text);  // quietly: the text parses as a block
  void take(const Piece& piece);
  static bool holds_program(const ir::Block& b);
  void read(const Piece& piece);
  void load(const Piece& piece);     // the block's text, as the lexer reads it, into sanitized_
  IsoParser::BlockContext* parse();  // sanitized_ by the parser
  void open_brace(const Piece& at);
  void close_brace(const Piece& at);
  void finish_branch();
  void drop_branch();
  void orphan_head(SourceRange r);

  // Parse-tree walking.
  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  SourceRange range(antlr4::ParserRuleContext* ctx) const { return range(ctx->getStart(), ctx->getStop()); }
  template <typename Ctx, typename Part, typename Read, typename OpOf>
  ir::ExprId chain(Ctx* ctx, const std::vector<Part*>& parts, Read operand_of, OpOf op_of);
  ir::ExprId expr(IsoParser::ExprContext* ctx);
  ir::ExprId and_expr(IsoParser::AndExprContext* ctx);
  ir::ExprId compare(IsoParser::CompareContext* ctx);
  ir::ExprId sum(IsoParser::SumContext* ctx);
  ir::ExprId term(IsoParser::TermContext* ctx);
  ir::ExprId factor(IsoParser::FactorContext* ctx);
  ir::ExprId primary(IsoParser::PrimaryContext* ctx);
  ir::ExprId variable(IsoParser::VariableContext* ctx, bool target);
  ir::ExprId value(IsoParser::ValueContext* ctx, bool& literal_integer);
  [[nodiscard]] std::optional<double> number(antlr4::tree::TerminalNode* n);
  ir::ExprId operand(ir::ExprId e);  // vacant reads as 0
  ir::ExprId checked(ir::ExprId e, const ir::Word& w, const std::string& address, double lo, double hi);
  ir::ExprId condition(IsoParser::ExprContext* ctx, const char* what);
  ir::Stmt assignment(IsoParser::AssignmentContext* ctx);
  ir::Stmt go_to(IsoParser::GotoStmtContext* ctx);
  // An address word as the block writes it, from the parse tree or the fast path.
  struct RawWord {
    char letter = 0;
    ir::ExprId value = ir::kNoExpr;
    std::string text;      // the value as written, without blanks: "-10.5", "#1", "[#2+1]"
    SourceRange range;     // the whole word
    bool literal = false;  // a number written without a decimal point
  };
  struct FastBlock {  // a block of address words only (the fast path)
    bool skip = false;
    bool has_errors = false;                                      // a number out of range (reported)
    std::optional<std::pair<std::string, SourceRange>> sequence;  // N's digits
    std::vector<RawWord> words;
  };
  [[nodiscard]] bool scan_plain(FastBlock& out);
  // Kept from block to block, so that reading a plain block allocates little.
  FastBlock fast_;
  PlainBlock plain_words_;
  std::vector<bool> literal_integer_;
  std::string absent_axes_;  // axis letters the machine lacks, said once each
  RawWord raw_word(antlr4::tree::TerminalNode* letter, IsoParser::ValueContext* v, SourceRange r, bool address);
  void number_block(const std::string& digits, SourceRange r, size_t index);
  void finish_read(size_t index);
  void words(IsoParser::WordsContext* ctx, ir::ExprId cond);
  void words(const std::vector<RawWord>& list, const RawWord* corner, ir::ExprId cond);
  void call_words(ir::ExprId cond);
  void g92_words(size_t first);
  [[nodiscard]] std::optional<uint32_t> whole(const ir::Word& w, uint32_t min, uint32_t max, const char* what);

  // Structure.
  ir::Block& new_block(SourceRange r);
  std::string label_of(size_t block);
  void start_unit(ir::UnitKind kind, std::string name, SourceRange r);
  void end_unit();

  const Settings& s_;
  ir::Program& program_;
  const SourceFile& source_;
  uint32_t file_;
  Diagnostics& diags_;
  uint16_t space_;  // the Macro B variables #0..#999
  std::optional<std::string> called_;
  bool fast_path_;
  BlockSink* sink_;

  antlr4::ANTLRInputStream input_;
  IsoLexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  IsoParser parser_{&tokens_};
  std::unique_ptr<BlockErrors> errors_;
  std::string sanitized_;
  uint32_t line_ = 0, base_ = 0;  // of the piece being parsed

  ir::Unit unit_;
  bool in_unit_ = false;
  bool main_done_ = false;           // the main program has ended (M02/M30): O units may follow
  int digits_told_ = 0;              // the note on iso.program_number_digits was given
  std::optional<size_t> end_block_;  // the main program's M02/M30 block
  // The main program's M99s, reported (NC3044) unless it is a macro of a library
  // (decision 71): an O program whose last acting block is M99, with no M02/M30.
  std::vector<SourceRange> main_returns_;
  bool main_returns_last_ = false;  // the main program's last acting block so far is M99
  bool main_is_macro() const;
  void end_main();
  std::optional<SourceRange> nested_at_;  // the first nested comment (decision 55)
  uint32_t nested_lines_ = 0, nested_line_ = 0;
  std::optional<SourceRange> semicolon_at_;  // the first ';' that starts a comment (decision 54)
  uint32_t semicolon_lines_ = 0;             // the lines after it that do so too
  std::vector<Loop> loops_;
  std::vector<Branch> branches_;
  bool expect_brace_ = false;  // a multi-line IF head waits for its '{'
  struct LocalCall {
    std::string label;  // "N100"
    SourceRange range;
    size_t block = 0;
  };
  std::vector<LocalCall> local_calls_;  // the M97 calls of this unit
  size_t next_label_ = 0;
  bool in_word_ = false;               // reading an address's value (ROUND keeps decimals there)
  std::optional<SourceRange> corner_;  // the ,C or ,R of the block before (E-05)
  std::vector<ProgramCall> calls_;
  ir::Block block_;  // being read
};

}  // namespace ncc::iso
