// Reads one linuxcnc file: a line is a block. Takes the comments out (`( )`, `;` to
// the end of the line; `(MSG,` and `(DEBUG,` are messages), upper-cases the rest and
// drops its blanks as LinuxCNC does, parses it with the ANTLR grammar and builds the
// o-word structure (sub/endsub, if/elseif/else/endif, while, do/while, repeat,
// break/continue, call and return) and the Fanuc-style O programs of M98/M99 into IR.
#pragma once

#include <antlr4-runtime.h>

#include <map>
#include <optional>

#include "LinuxcncLexer.h"
#include "LinuxcncParser.h"
#include "frontend/block_errors.h"
#include "frontend/frontend.h"
#include "ir/ir.h"
#include "settings.h"

namespace ncc::linuxcnc {

using ncc_linuxcnc::LinuxcncLexer;
using ncc_linuxcnc::LinuxcncParser;

// The parameters of a program, shared by every file it reads: the numbered ones
// (#1-#30 local to a call), the named locals (#<x>) and globals (#<_x>), each name
// given an index in its space on first use.
struct Parameters {
  uint16_t numbered = 0, locals = 1, globals = 2;            // variable spaces
  static constexpr uint32_t kValue = 1, kValueReturned = 2;  // #<_value>, #<_value_returned>
  std::map<std::string, uint32_t> local_names, global_names{{"_value", kValue}, {"_value_returned", kValueReturned}};
  uint32_t temporaries = 0;  // #5603...: a line's values while its parameters are set
};

// A call of a subroutine the file does not define, for the front end to find.
struct SubCall {
  std::string name;  // "o<name>", "o100"
  SourceRange range;
  std::string unit;  // the calling unit's name
  size_t block = 0;
};

class Reader {
 public:
  Reader(const Settings& settings, ir::Program& program, Parameters& params, const SourceFile& source, uint32_t file,
         Diagnostics& diags, bool called);
  ~Reader();

  // Appends the file's units to the program: the main program (unless the file was
  // called) and its subroutines.
  void run();
  const std::vector<SubCall>& calls() const { return calls_; }
  // The unit names this file defined.
  const std::vector<std::string>& defined() const { return defined_; }

 private:
  struct Open;

  void line(uint32_t n);
  void load(uint32_t n, std::string_view text, const std::vector<std::pair<size_t, size_t>>& comments);
  LinuxcncParser::BlockContext* parse();
  void read_block(LinuxcncParser::BlockContext* ctx, ir::Block& b);
  void oword(LinuxcncParser::OwordContext* ctx, ir::Block& b);
  void messages(const std::vector<std::string>& comments, ir::Block& b);
  void items(LinuxcncParser::BlockContext* ctx, ir::Block& b);
  void call_words(ir::Block& b, size_t code);

  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  SourceRange range(antlr4::ParserRuleContext* ctx) const { return range(ctx->getStart(), ctx->getStop()); }
  ir::ExprId binary(antlr4::ParserRuleContext* ctx, const std::vector<ir::ExprId>& operands);
  template <typename Ctx, typename Part>
  ir::ExprId level(Ctx* ctx, const std::vector<Part*>& parts, ir::ExprId (Reader::*read)(Part*));
  ir::ExprId expr(LinuxcncParser::ExprContext* ctx);
  ir::ExprId compare(LinuxcncParser::CompareContext* ctx);
  ir::ExprId sum(LinuxcncParser::SumContext* ctx);
  ir::ExprId term(LinuxcncParser::TermContext* ctx);
  ir::ExprId power(LinuxcncParser::PowerContext* ctx);
  ir::ExprId factor(LinuxcncParser::FactorContext* ctx);
  ir::ExprId call(LinuxcncParser::CallContext* ctx);
  ir::ExprId value(LinuxcncParser::ValueContext* ctx);
  ir::ExprId variable(LinuxcncParser::VariableContext* ctx, bool target);
  ir::ExprId number(antlr4::tree::TerminalNode* n);
  ir::ExprId global(uint32_t index, SourceRange r);

  // Structure.
  ir::Block& new_block(SourceRange r);
  std::string label_of(size_t block);
  void start_sub(const std::string& name, SourceRange r, bool fanuc);
  void end_sub();
  void returns(ir::Block& b, ir::ExprId value);
  void land(const std::vector<std::pair<size_t, size_t>>& jumps, const std::string& label);
  Open* innermost(const std::string& name, SourceRange r, const char* what);

  const Settings& s_;
  ir::Program& program_;
  Parameters& params_;
  const SourceFile& source_;
  uint32_t file_;
  Diagnostics& diags_;
  bool called_;

  antlr4::ANTLRInputStream input_;
  LinuxcncLexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  LinuxcncParser parser_{&tokens_};
  std::unique_ptr<BlockErrors> errors_;
  std::string sanitized_;
  std::vector<uint32_t> columns_;  // of each character of sanitized_ (1-based), and one past its end
  uint32_t line_ = 0;

  ir::Unit main_, sub_;
  bool in_sub_ = false, fanuc_sub_ = false;
  bool ended_ = false;  // the main program's M2/M30 has been read
  bool percent_ = false, closed_ = false;
  bool read_any_ = false;  // a line that is not blank
  std::vector<Open> open_;
  size_t next_label_ = 0;
  std::vector<SubCall> calls_;
  std::vector<std::string> defined_;
  ir::Unit& unit() { return in_sub_ ? sub_ : main_; }
};

}  // namespace ncc::linuxcnc
