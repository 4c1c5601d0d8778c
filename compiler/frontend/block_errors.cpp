#include "block_errors.h"

#include <algorithm>

#include "frontend.h"

namespace ncc {

void BlockErrors::start(uint32_t file, uint32_t line, std::string_view text, size_t length,
                        std::function<uint32_t(size_t)> column) {
  file_ = file;
  line_ = line;
  text_ = text;
  length_ = length;
  column_ = std::move(column);
  any_ = false;
  quiet_ = false;
}

void BlockErrors::syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* token, size_t, size_t position,
                              const std::string&, std::exception_ptr) {
  if (any_) return;  // one message a block: the rest follows from it
  any_ = true;
  if (quiet_) return;
  // A letter with no value after it (`P F15.04`): the letter's error, not the next's.
  auto* parser = dynamic_cast<antlr4::Parser*>(recognizer);
  const auto& starts = tokens_.value_starts;
  if (tokens_.letter && token && parser && std::find(starts.begin(), starts.end(), token->getType()) == starts.end()) {
    for (size_t k = token->getTokenIndex(); k-- > 0;) {
      antlr4::Token* before = parser->getTokenStream()->get(k);
      if (before->getChannel() != antlr4::Token::DEFAULT_CHANNEL) continue;
      if (before->getType() == tokens_.letter) {
        const uint32_t at = column_(before->getStartIndex());
        diags_.report(DiagId::ValueMissing, {file_, line_, at, line_, at + 1}, before->getText());
        return;
      }
      break;
    }
  }
  const bool eof = !token || token->getType() == antlr4::Token::EOF;
  const uint32_t col = column_(eof ? length_ : token ? token->getStartIndex() : position);
  if (!eof && token->getType() == tokens_.invalid) {
    size_t length = 1;
    std::string what = describe_char(text_, col - 1, length);
    diags_.report(DiagId::CharInvalid, {file_, line_, col, line_, col + static_cast<uint32_t>(length)}, what);
    return;
  }
  std::string what = eof ? std::string("end of text") : fmt::format("'{}'", token->getText());
  const uint32_t end = eof ? col + 1 : column_(token->getStopIndex()) + 1;
  diags_.report(DiagId::SyntaxError, {file_, line_, col, line_, end}, what);
}

}  // namespace ncc
