// UTF-8, strictly (RFC 3629): the one decoder every stage uses for text from a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ncc {

// One character of UTF-8 text; `length` 0 when the bytes are not one: a continuation
// byte without its lead, a lead without all its continuation bytes (cut off), an
// overlong form (C0, C1, E0 80..9F, F0 80..8F), a surrogate (ED A0..BF) or a code
// point above U+10FFFF (F4 90.., F5..FF).
struct Utf8Char {
  uint32_t code_point = 0;
  uint8_t length = 0;
};
Utf8Char decode_utf8(std::string_view s, size_t at);

// The offset of the first byte of `s` that is not UTF-8 text, or npos.
size_t find_invalid_utf8(std::string_view s);

// `s` with each byte that is not UTF-8 written `\xF4` (four columns): what ncc prints
// of untrusted text stays valid UTF-8.
std::string escape_invalid_utf8(std::string_view s);

}  // namespace ncc
