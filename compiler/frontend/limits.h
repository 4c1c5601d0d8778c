// What every front end refuses before it reads (docs/limits.md, "Text and nesting"):
// a file that is not text, a block too long to read, an expression nested or chained
// beyond any real program. Each limit lies far above what programs and controls use,
// and together they bound the recursion of the ANTLR parsers and of every walk over
// the IR built from their trees (the IR printer, the lowering), so that ncc runs in a
// thread with a small stack.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "support/diagnostics.h"

namespace antlr4 {
class ANTLRInputStream;
class BufferedTokenStream;
class CommonTokenStream;
class Lexer;
class Token;
}  // namespace antlr4

namespace ncc {

inline constexpr size_t kMaxBlockBytes = 4096;  // a block, comments included
inline constexpr size_t kMaxNesting = 32;       // brackets, parentheses and function calls
inline constexpr size_t kMaxSignsInARow = 8;    // signs before one value (`--1`)
inline constexpr size_t kMaxOperators = 256;    // binary operators in a block

// A file just read: false when it is binary data (NC1009) or not UTF-8 text (NC1035),
// reported once at its first bad byte; such a file is not read. Nothing after this
// sees bytes that are not UTF-8.
[[nodiscard]] bool admit_text(const SourceFile& source, uint32_t file, Diagnostics& diags);

// A block of `bytes` starting at `at`: false (reported) beyond kMaxBlockBytes, and the
// block is not read.
[[nodiscard]] bool block_fits(size_t bytes, SourceRange at, Diagnostics& diags);

// A grammar's token types the expression limits count.
struct ExpressionTokens {
  std::vector<size_t> open;          // '[' '(': one level deeper (a function call opens one too)
  std::vector<size_t> close;         // ']' ')'
  std::vector<size_t> signs;         // '+' '-': a binary operator after an operand, else a sign
  std::vector<size_t> operators;     // the other binary operators: '*' '/' AND EQ ...
  std::vector<size_t> operand_ends;  // what can end an operand: a number, a name, ']'
};

// Whether the block's tokens (all lexed: the stream is filled) stay within the
// nesting, sign and operator limits; false when not, reported at the first token
// beyond, whose source range `range` gives. Scanned before parsing, in a loop: a
// block beyond them is not parsed.
using TokenRange = std::function<SourceRange(antlr4::Token* first, antlr4::Token* last)>;
[[nodiscard]] bool expression_fits(antlr4::BufferedTokenStream& tokens, const ExpressionTokens& kinds,
                                   const TokenRange& range, Diagnostics& diags);

// Lexes a block's `text` into `tokens` (which read `lexer`, which reads `input`: a
// reader keeps the three from block to block) and checks them as expression_fits
// does; false (reported) when the block is beyond the limits: it is not parsed.
[[nodiscard]] bool lex_block(const std::string& text, antlr4::ANTLRInputStream& input, antlr4::Lexer& lexer,
                             antlr4::CommonTokenStream& tokens, const ExpressionTokens& kinds, const TokenRange& range,
                             Diagnostics& diags);

}  // namespace ncc
