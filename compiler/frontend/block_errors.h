// The ANTLR error listener of a front end that parses a block at a time: the block's
// first syntax error becomes one diagnostic at its column in the source line.
#pragma once

#include <antlr4-runtime.h>

#include <functional>
#include <string_view>
#include <vector>

#include "support/diagnostics.h"

namespace ncc {

// The lexer's token types the listener needs to name an error's cause.
struct BlockTokens {
  size_t invalid = 0;                // a character no other token takes
  size_t letter = 0;                 // an address letter; 0: not checked
  std::vector<size_t> value_starts;  // the tokens a letter's value may begin with
};

class BlockErrors final : public antlr4::BaseErrorListener {
 public:
  BlockErrors(BlockTokens tokens, Diagnostics& diags) : tokens_(std::move(tokens)), diags_(diags) {}
  // A block of `length` characters as the lexer reads it, on line `line` of `file`
  // whose text is `text`; `column(i)`: the 1-based column of its character i (i =
  // length: where it ends).
  void start(uint32_t file, uint32_t line, std::string_view text, size_t length,
             std::function<uint32_t(size_t)> column);
  // A parse that only asks whether the text is a block: nothing is reported.
  void start_quiet() {
    any_ = false;
    quiet_ = true;
  }
  bool any() const { return any_; }

  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t, size_t position, const std::string&,
                   std::exception_ptr) override;

 private:
  BlockTokens tokens_;
  Diagnostics& diags_;
  uint32_t file_ = 0, line_ = 0;
  std::string_view text_;
  size_t length_ = 0;
  std::function<uint32_t(size_t)> column_;
  bool any_ = false;
  bool quiet_ = false;
};

}  // namespace ncc
