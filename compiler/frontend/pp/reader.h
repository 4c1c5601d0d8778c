// Reads one pp file: the tape (leader, '%' line, blocks from N to N, '*'), each block
// through the ANTLR grammar, and the program structure (main part ended by M02/M30,
// subprograms G79 L ... G70, or the one macro of a macro file) into IR units.
#pragma once

#include <antlr4-runtime.h>

#include <map>
#include <optional>

#include "PpLexer.h"
#include "PpParser.h"
#include "frontend/plain_words.h"
#include "ir/ir.h"
#include "settings.h"

namespace ncc::pp {

using ncc_pp::PpLexer;
using ncc_pp::PpParser;

// A G72 call, for the front end to read the macro file it names.
struct MacroCall {
  uint32_t number = 0;  // L
  SourceRange range;    // of the L word
  size_t unit = 0, block = 0;
};

// Where the spaces of the program are (one set for every file of it).
struct Spaces {
  uint16_t r = 0;             // R0..R95
  uint16_t counters = 0;      // one jump counter per G73 block, local to each call
  uint32_t next_counter = 0;  // the counters given out so far
};

class Reader {
 public:
  // `macro`: the file of macro L`macro` (a G72 call), else the main file.
  Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file, Diagnostics& diags,
         Spaces& spaces, std::optional<uint32_t> macro, bool fast_path);

  // Appends the file's units to the program.
  void run();
  const std::vector<MacroCall>& macro_calls() const { return macro_calls_; }

  // The file a macro lives in: L and its number in four digits (decision 13).
  static std::string macro_name(uint32_t number);

 private:
  struct Piece {  // where a block's text starts
    uint32_t line = 0, col = 0;  // 1-based
    size_t begin = 0, end = 0;   // byte offsets in the file
  };
  // What a block does to the program's structure and flow.
  struct Flow {
    const ir::Word* control_word[9] = {};  // by Control: the code that asked for it
    std::optional<uint32_t> l;              // L, when written as a number
    const ir::Word* l_word = nullptr;
    const ir::Word* q_word = nullptr;
    const ir::Word* ends_main = nullptr;  // M02 or M30
  };

  void read_tape();
  void load(const Piece& piece);  // hands the text of `piece` to the parser
  void read_start(uint32_t line_no, size_t pct);
  void read_block(const Piece& piece);
  bool scan_plain(const Piece& piece);  // the fast path: a block of address words only
  void block_number(std::string_view digits, SourceRange r, bool bare);
  void build_units();

  // Token handling.
  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  void element(PpParser::ElementContext* ctx, size_t index, const std::vector<PpParser::ElementContext*>& all);
  void word(std::string_view written, SourceRange r);  // "X 12.5"
  void parameter(antlr4::Token* t);
  void damaged(antlr4::Token* t, antlr4::Token* previous);
  std::optional<ir::ExprId> value(std::string_view text, char letter, const stdlib::AddressEntry& entry,
                                  SourceRange r, const std::string& shown);
  ir::ExprId r_value(uint32_t index, bool negative, SourceRange r);
  std::string comment_text(antlr4::Token* t) const;

  void finish_block();
  Flow flow_of(const ir::Block& b) const;

  const Settings& s_;
  ir::Program& program_;
  const SourceFile& source_;
  uint32_t file_;
  Diagnostics& diags_;
  Spaces& spaces_;
  std::optional<uint32_t> macro_;
  bool fast_path_;
  PlainBlock plain_;

  antlr4::ANTLRInputStream input_;
  PpLexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  PpParser parser_{&tokens_};
  std::string sanitized_;
  Piece piece_;  // the text being parsed

  std::string number_;  // the program number, "%35"
  std::string title_;
  SourceRange start_range_;
  std::vector<ir::Block> blocks_;
  ir::Block block_;
  struct Assignment {
    uint32_t index;
    ir::ExprId value;
    SourceRange range;
  };
  std::vector<Assignment> assignments_;
  bool slash_ = false;
  std::vector<MacroCall> macro_calls_;
};

}  // namespace ncc::pp
