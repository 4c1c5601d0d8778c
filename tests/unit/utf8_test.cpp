// The strict UTF-8 decoder every stage reads text with, and what the diagnostic
// printer makes of bytes that are not UTF-8.
#include <gtest/gtest.h>

#include "support/diagnostics.h"
#include "support/utf8.h"

namespace ncc {
namespace {

// The code point of the one character `bytes` are, or -1 when they are not exactly one.
int64_t one(std::string_view bytes) {
  const Utf8Char c = decode_utf8(bytes, 0);
  return c.length == bytes.size() ? static_cast<int64_t>(c.code_point) : -1;
}

TEST(Utf8, DecodesEachLengthToItsBounds) {
  EXPECT_EQ(one("A"), 0x41);
  EXPECT_EQ(one(std::string_view("\0", 1)), 0);
  EXPECT_EQ(one("\x7F"), 0x7F);
  EXPECT_EQ(one("\xC2\x80"), 0x80);
  EXPECT_EQ(one("\xDF\xBF"), 0x7FF);
  EXPECT_EQ(one("Д"), 0x414);
  EXPECT_EQ(one("\xE0\xA0\x80"), 0x800);
  EXPECT_EQ(one("\xED\x9F\xBF"), 0xD7FF);  // the last before the surrogates
  EXPECT_EQ(one("\xEE\x80\x80"), 0xE000);  // the first after them
  EXPECT_EQ(one("–"), 0x2013);
  EXPECT_EQ(one("\xEF\xBF\xBF"), 0xFFFF);
  EXPECT_EQ(one("\xF0\x90\x80\x80"), 0x10000);
  EXPECT_EQ(one("\xF4\x8F\xBF\xBF"), 0x10FFFF);
}

TEST(Utf8, RefusesEveryInvalidClass) {
  const char* invalid[] = {
      "\x80",
      "\xBF",  // a continuation byte without its lead
      "\xC0\x80",
      "\xC1\xBF",  // overlong two-byte forms (of U+0000, U+007F)
      "\xE0\x80\x80",
      "\xE0\x9F\xBF",  // overlong three-byte forms (below U+0800)
      "\xF0\x80\x80\x80",
      "\xF0\x8F\xBF\xBF",  // overlong four-byte forms (below U+10000)
      "\xED\xA0\x80",
      "\xED\xBF\xBF",      // surrogates U+D800, U+DFFF
      "\xF4\x90\x80\x80",  // U+110000: the byte sequence
      "\xF5\x80\x80\x80",
      "\xF7\xBF\xBF\xBF",
      "\xF8\x88\x80\x80\x80",
      "\xFF",
      "\xFE",  // no such lead byte
      "\xC3",
      "\xE2\x82",
      "\xF0\x9F\x98",  // cut off before the end
      "\xC3\x41",
      "\xE2\x41\xAC",
      "\xF0\x9F\x41\x80",  // a byte that is no continuation
  };
  for (const char* bytes : invalid) {
    EXPECT_EQ(decode_utf8(bytes, 0).length, 0) << testing::PrintToString(std::string(bytes));
    EXPECT_EQ(find_invalid_utf8(bytes), 0u) << testing::PrintToString(std::string(bytes));
  }
}

TEST(Utf8, FindsTheFirstBadByte) {
  EXPECT_EQ(find_invalid_utf8("G1 X10 (ДЕТАЛЬ) – M30"), std::string_view::npos);
  EXPECT_EQ(find_invalid_utf8(""), std::string_view::npos);
  EXPECT_EQ(find_invalid_utf8("G1 X\xF4\x90\x80\x80"
                              "0 Y0\nM30\n"),
            4u);
  EXPECT_EQ(find_invalid_utf8("(\xCF\xC5\xD0)"), 1u);  // CP1251 "ПЕР"
  EXPECT_EQ(find_invalid_utf8("ДЕ\xD0"), 4u);          // cut off at the end of the text
}

TEST(Utf8, EscapesBadBytesAndKeepsTheRest) {
  EXPECT_EQ(escape_invalid_utf8("X\xF4\x90\x80\x80"
                                "1 Д"),
            "X\\xF4\\x90\\x80\\x801 Д");
  EXPECT_EQ(escape_invalid_utf8("plain"), "plain");
}

TEST(Utf8, QuotedLineEscapesBadBytesWithTheCaretUnderThem) {
  SourceManager sources;
  const uint32_t f = sources.add("p.nc",
                                 "(Д) X\xF4\x90\x80\x80"
                                 "0 Y0\n");
  Diagnostics diags;
  // The bad byte at byte column 7 prints as four columns after five.
  Diagnostic* d = diags.report(DiagId::SyntaxError, {f, 1, 7, 1, 8}, "byte 0xF4");
  d->notes.push_back({{f, 1, 11, 1, 12}, "the '0' after them"});
  EXPECT_EQ(format_text(*d, sources),
            "p.nc:1:7: error: unexpected byte 0xF4 in the block [NC1014]\n"
            "    1 | (Д) X\\xF4\\x90\\x80\\x800 Y0\n"
            "      |      ^~~~\n"
            "p.nc:1:11: note: the '0' after them\n"
            "    1 | (Д) X\\xF4\\x90\\x80\\x800 Y0\n"
            "      |                      ^\n");
}

TEST(Utf8, MessagesAndPathsPrintAsValidUtf8) {
  SourceManager sources;
  const uint32_t f = sources.add("\xFF.nc", "X1\n");
  Diagnostics diags;
  Diagnostic* d = diags.report(DiagId::SyntaxError, {f, 1, 1, 1, 2}, "'\xC0'");
  EXPECT_EQ(format_text(*d, sources),
            "\\xFF.nc:1:1: error: unexpected '\\xC0' in the block [NC1014]\n"
            "    1 | X1\n"
            "      | ^\n");
  const std::string json = format_all(diags.all(), sources, DiagFormat::Json);
  EXPECT_EQ(find_invalid_utf8(json), std::string_view::npos) << json;
  EXPECT_NE(json.find("\\ufffd.nc"), std::string::npos) << json;
}

TEST(Utf8, LongLineWindowCountsEscapedBytesAsTheirColumns) {
  SourceManager sources;
  // 200 bad bytes, then the column: the window holds 60 columns before it (15 bytes).
  const uint32_t f = sources.add("p.nc", std::string(200, '\xFF') + "X1\n");
  Diagnostics diags;
  Diagnostic* d = diags.report(DiagId::SyntaxError, {f, 1, 201, 1, 202}, "'X'");
  const std::string text = format_text(*d, sources);
  std::string window = "...";
  for (int i = 0; i < 15; ++i) window += "\\xFF";
  EXPECT_NE(text.find("    1 | " + window + "X1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n      | " + std::string(63, ' ') + "^\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace ncc
