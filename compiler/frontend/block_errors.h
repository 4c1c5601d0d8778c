// The ANTLR error listener of a front end that parses a block at a time: the block's
// first syntax error becomes one diagnostic at its column in the source line.
#pragma once

#include <antlr4-runtime.h>

#include <functional>
#include <string_view>

#include "support/diagnostics.h"

namespace ncc {

class BlockErrors final : public antlr4::BaseErrorListener {
 public:
  // `invalid`: the lexer's token type for a character no other token takes.
  BlockErrors(size_t invalid, Diagnostics& diags) : invalid_(invalid), diags_(diags) {}
  // A block of `length` characters as the lexer reads it, on line `line` of `file`
  // whose text is `text`; `column(i)`: the 1-based column of its character i (i =
  // length: where it ends).
  void start(uint32_t file, uint32_t line, std::string_view text, size_t length,
             std::function<uint32_t(size_t)> column);
  bool any() const { return any_; }

  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t, size_t position, const std::string&,
                   std::exception_ptr) override;

 private:
  size_t invalid_;
  Diagnostics& diags_;
  uint32_t file_ = 0, line_ = 0;
  std::string_view text_;
  size_t length_ = 0;
  std::function<uint32_t(size_t)> column_;
  bool any_ = false;
};

}  // namespace ncc
