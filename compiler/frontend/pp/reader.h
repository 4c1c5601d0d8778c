// Reads one pp file: the tape (leader, '%' line, blocks from N to N, '*'), each block
// through the ANTLR grammar, and the program structure (main part ended by M02/M30,
// subprograms G79 L ... G70, or the one macro of a macro file) into IR units. The
// main part's blocks go to the sink as they are read, up to its first call or jump.
#pragma once

#include <antlr4-runtime.h>

#include <map>
#include <optional>

#include "PpLexer.h"
#include "PpParser.h"
#include "frontend/frontend.h"
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
         Spaces& spaces, std::optional<uint32_t> macro, bool fast_path, BlockSink* sink = nullptr);

  // Appends the file's units to the program.
  void run();
  const std::vector<MacroCall>& macro_calls() const { return macro_calls_; }

  // The file a macro lives in: L and its number in four digits (decision 13).
  static std::string macro_name(uint32_t number);

 private:
  struct Piece {                 // where a block's text starts
    uint32_t line = 0, col = 0;  // 1-based
    size_t begin = 0, end = 0;   // byte offsets in the file
  };
  // What a block does to the program's structure and flow.
  struct Flow {
    const ir::Word* control_word[9] = {};  // by Control: the code that asked for it
    std::optional<uint32_t> l;             // L, when written as a number
    const ir::Word* l_word = nullptr;
    const ir::Word* q_word = nullptr;
    const ir::Word* ends_main = nullptr;  // M02 or M30
  };

  void read_tape();
  void load(const Piece& piece);  // hands the text of `piece` to the parser
  void read_start(uint32_t line_no, size_t pct);
  void read_block(const Piece& piece);
  [[nodiscard]] bool scan_plain(const Piece& piece);  // the fast path: a block of address words only
  void block_number(std::string_view digits, SourceRange r, bool bare);
  void place_block();  // the block just read, in the main part or after it
  // Adds a call's statement, or notes a jump for resolve_jumps; true for either.
  bool flow(ir::Block& b, const Flow& f, size_t unit, const ir::Unit& in);
  void structure(const ir::Block& b, const std::string& what);
  struct Span {
    size_t begin, end;  // the unit's blocks, by their place in the file
  };
  void build_units();
  void resolve_jumps(const std::vector<Span>& spans);

  // Token handling.
  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  void element(PpParser::ElementContext* ctx, size_t index, const std::vector<PpParser::ElementContext*>& all);
  void word(std::string_view written, SourceRange r);  // "X 12.5"
  void parameter(antlr4::Token* t);
  void damaged(antlr4::Token* t, antlr4::Token* previous);
  [[nodiscard]] std::optional<ir::ExprId> value(std::string_view text, char letter, const stdlib::AddressEntry& entry,
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
  BlockSink* sink_;
  size_t first_unit_;  // the program's units before this file's
  PlainBlock plain_;

  antlr4::ANTLRInputStream input_;
  PpLexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  PpParser parser_{&tokens_};
  std::string sanitized_;
  Piece piece_;                 // the text being parsed
  bool char_reported_ = false;  // the block's first character outside the alphabet is

  std::string number_;  // the program number, "%35"
  std::string title_;
  SourceRange start_range_;
  ir::Unit main_;                  // the main part, as the sink leaves it
  bool in_main_;                   // up to the block with M02 or M30
  bool streaming_;                 // the sink takes the main part's blocks
  std::vector<ir::Block> blocks_;  // after the main part, or the macro file's
  uint32_t read_ = 0;              // the blocks read so far
  SourceRange last_range_;         // of the last of them
  // The file's block numbers: they rise in most files, so those stand in order in a
  // vector (a binary search finds them), the others in a map.
  struct Numbered {
    uint32_t number;
    uint32_t at;        // the block's place in the file
    SourceRange range;  // of the N word
  };
  std::vector<Numbered> rising_;
  std::map<uint32_t, Numbered> others_;
  const Numbered* numbered(uint32_t number) const;
  struct Jump {
    size_t unit, block;  // the unit among this file's, the block in it
  };
  std::vector<Jump> jumps_;
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
