#include "block_errors.h"

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
}

void BlockErrors::syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t, size_t position, const std::string&,
                              std::exception_ptr) {
  if (any_) return;  // one message a block: the rest follows from it
  any_ = true;
  const bool eof = !token || token->getType() == antlr4::Token::EOF;
  const uint32_t col = column_(eof ? length_ : token ? token->getStartIndex() : position);
  if (!eof && token->getType() == invalid_) {
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
