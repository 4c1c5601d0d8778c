// The GOST 20999 §9 format descriptor and number decoding: every worked example of
// the reference (spec S-6.5) row by row.
#include <gtest/gtest.h>

#include "frontend/gost/format.h"

namespace ncc::gost {
namespace {

WordFormat word_format(std::string_view item) {
  std::vector<FormatProblem> problems;
  auto f = parse_format(item, problems);
  EXPECT_TRUE(f) << item;
  return f ? *f->word(item[0]) : WordFormat{};
}

WrittenNumber written(std::string_view text) {
  WrittenNumber n;
  size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    n.has_sign = true;
    n.negative = text[i] == '-';
    ++i;
  }
  for (; i < text.size(); ++i) {
    if (text[i] == '.')
      n.has_point = true;
    else
      (n.has_point ? n.after : n.before) += text[i];
  }
  return n;
}

struct Result {
  std::optional<double> value;
  std::string code;  // "" when no diagnostic
};

Result decode_word(std::string_view format, std::string_view number, bool ds, Mode mode = Mode::Default,
                   bool ds_implied = false) {
  Diagnostics diags;
  DecodeOptions opts{ds, ds_implied, mode};
  Result r;
  r.value = decode(format[0], word_format(format), written(number), opts, {}, diags);
  if (!diags.all().empty()) r.code = diag_code(diags.all().front().id);
  return r;
}

void expect_value(std::string_view format, std::string_view number, bool ds, double expected) {
  Result r = decode_word(format, number, ds);
  ASSERT_TRUE(r.value) << format << " " << number << (ds ? " DS" : " implied") << " gave " << r.code;
  EXPECT_DOUBLE_EQ(*r.value, expected) << format << " " << number << (ds ? " DS" : " implied");
  EXPECT_EQ(r.code, "") << format << " " << number;
}

void expect_error(std::string_view format, std::string_view number, bool ds, std::string_view code) {
  Result r = decode_word(format, number, ds);
  EXPECT_FALSE(r.value) << format << " " << number;
  EXPECT_EQ(r.code, code) << format << " " << number << (ds ? " DS" : " implied");
}

constexpr bool kImplied = false, kDs = true;

TEST(FormatDescriptor, StandardExample) {
  // §9.3: % : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02 *
  std::vector<FormatProblem> problems;
  auto f = parse_format("% : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02 *", problems);
  ASSERT_TRUE(f);
  EXPECT_TRUE(problems.empty());
  EXPECT_TRUE(f->program_start && f->main_block && f->block_skip && f->decimal_sign);
  const WordFormat& x = *f->word('X');
  EXPECT_TRUE(x.dimension && x.is_signed);
  EXPECT_EQ(x.int_digits, 5);
  EXPECT_EQ(x.frac_digits, 3);
  EXPECT_EQ(x.suppress, Suppress::Leading);
  const WordFormat& feed = *f->word('F');
  EXPECT_FALSE(feed.is_signed);
  EXPECT_EQ(feed.int_digits, 3);
  EXPECT_EQ(feed.frac_digits, 1);
  const WordFormat& n = *f->word('N');
  EXPECT_FALSE(n.dimension);
  EXPECT_EQ(n.int_digits, 3);
  EXPECT_EQ(n.suppress, Suppress::Leading);
  EXPECT_EQ(f->word('M')->int_digits, 2);
  EXPECT_EQ(f->word('H'), nullptr);
}

TEST(FormatDescriptor, FileSkipsCommentLines) {
  EXPECT_EQ(format_line_of_file("(comment)\n  (another one)\r\n% : DS X+053 *\nignored\n"), "% : DS X+053 *");
}

TEST(FormatDescriptor, InvalidItems) {
  for (std::string_view bad : {"X+5", "X00", "X000", "X+123", "G12", "N+3", "X+05a", "Q", "Z53 Z53", "%%"}) {
    std::vector<FormatProblem> problems;
    EXPECT_FALSE(parse_format(bad, problems)) << bad;
    ASSERT_FALSE(problems.empty()) << bad;
    EXPECT_TRUE(problems.front().error) << bad;
  }
}

TEST(FormatDescriptor, AmbiguousZeroAZero) {
  // 0a0 reads as leading suppression with a integer digits (S-6.3), with a warning.
  std::vector<FormatProblem> problems;
  auto f = parse_format("F030", problems);
  ASSERT_TRUE(f);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_FALSE(problems[0].error);
  EXPECT_EQ(f->word('F')->int_digits, 3);
  EXPECT_EQ(f->word('F')->frac_digits, 0);
  EXPECT_EQ(f->word('F')->suppress, Suppress::Leading);
}

// S-6.5, format X+053 (signed, 5.3, leading zeros omitted).
TEST(Decode, X053Implied) {
  expect_value("X+053", "01234567", kImplied, 1234.567);
  expect_value("X+053", "1234567", kImplied, 1234.567);
  expect_value("X+053", "-1500", kImplied, -1.5);
  expect_value("X+053", "25", kImplied, 0.025);
  expect_value("X+053", "0", kImplied, 0);
  expect_value("X+053", "1030", kImplied, 1.03);
  expect_error("X+053", "123456789", kImplied, "NC2012");
  expect_error("X+053", "12.5", kImplied, "NC2004");
  expect_error("X+053", ".03", kImplied, "NC2004");
  expect_error("X+053", "1030.", kImplied, "NC2004");
  expect_error("X+053", "123456.", kImplied, "NC2004");
  expect_error("X+053", "1.2345", kImplied, "NC2004");
  expect_error("X+053", "", kImplied, "NC2002");
  expect_error("X+053", "-", kImplied, "NC2002");
  expect_error("X+053", ".", kImplied, "NC2002");
}

TEST(Decode, X053Explicit) {
  expect_error("X+053", "01234567", kDs, "NC2005");
  expect_error("X+053", "1234567", kDs, "NC2005");
  expect_value("X+053", "-1500", kDs, -1500);
  expect_value("X+053", "25", kDs, 25);
  expect_value("X+053", "0", kDs, 0);
  expect_error("X+053", "123456789", kDs, "NC2005");
  expect_value("X+053", "12.5", kDs, 12.5);
  expect_value("X+053", ".03", kDs, 0.03);
  expect_value("X+053", "1030.", kDs, 1030);
  expect_value("X+053", "1030", kDs, 1030);
  expect_error("X+053", "123456.", kDs, "NC2005");
  expect_error("X+053", "1.2345", kDs, "NC2006");
  expect_value("X+053", "1.2500", kDs, 1.25);
  expect_error("X+053", "", kDs, "NC2002");
  expect_error("X+053", "-", kDs, "NC2002");
  expect_error("X+053", ".", kDs, "NC2002");
}

// Format X+530: trailing zeros omitted; the digits align left.
TEST(Decode, X530TrailingImplied) {
  expect_value("X+530", "00012", kImplied, 12);
  expect_value("X+530", "000125", kImplied, 12.5);
  expect_value("X+530", "1", kImplied, 10000);
  expect_value("X+530", "-0001", kImplied, -10);
  expect_value("X+530", "00000001", kImplied, 0.001);
  expect_error("X+530", "000000001", kImplied, "NC2012");
}

// Format X+53: no suppression, exactly a + b digits.
TEST(Decode, X53NoSuppression) {
  expect_value("X+53", "00012500", kImplied, 12.5);
  expect_error("X+53", "125", kImplied, "NC2007");
  Result lenient = decode_word("X+53", "125", kImplied, Mode::Lenient);
  ASSERT_TRUE(lenient.value);
  EXPECT_DOUBLE_EQ(*lenient.value, 0.125);
  EXPECT_EQ(lenient.code, "NC2008");
}

TEST(Decode, UnsignedFormatRejectsSigns) {
  expect_error("X53", "-5", kImplied, "NC2003");
  expect_error("X53", "+5", kImplied, "NC2003");
  expect_value("X53", "00005000", kImplied, 5);
}

// Feed F031 (3.1, leading).
TEST(Decode, F031) {
  expect_value("F031", "1500", kImplied, 150.0);
  expect_error("F031", "1500", kDs, "NC2005");
  expect_value("F031", "15", kImplied, 1.5);
  expect_value("F031", "15", kDs, 15);
  expect_value("F031", "2", kImplied, 0.2);
  expect_value("F031", "2", kDs, 2);
  expect_error("F031", "150.5", kImplied, "NC2004");
  expect_value("F031", "150.5", kDs, 150.5);
}

// Non-dimension words (both modes).
TEST(Decode, NonDimension) {
  for (bool ds : {kImplied, kDs}) {
    expect_value("N03", "5", ds, 5);
    expect_value("N03", "05", ds, 5);
    expect_value("N03", "005", ds, 5);
    expect_error("N03", "1000", ds, "NC2012");
    expect_error("N3", "5", ds, "NC2007");
    expect_value("N3", "005", ds, 5);
    expect_value("G02", "1", ds, 1);
    expect_value("G02", "01", ds, 1);
    expect_value("S04", "800", ds, 800);
    expect_error("S04", "12345", ds, "NC2012");
    expect_value("M02", "3", ds, 3);
    expect_error("M02", "-3", ds, "NC2003");
    expect_error("G02", "1.", ds, "NC2004");
  }
}

TEST(Decode, DsImpliedRule) {
  // ds_integer_rule = implied: point-less words in DS mode read as implied.
  Result r = decode_word("X+053", "1500", kDs, Mode::Default, true);
  ASSERT_TRUE(r.value);
  EXPECT_DOUBLE_EQ(*r.value, 1.5);
  Result p = decode_word("X+053", "12.5", kDs, Mode::Default, true);
  ASSERT_TRUE(p.value);
  EXPECT_DOUBLE_EQ(*p.value, 12.5);
}

TEST(Decode, LongNumbersRoundCorrectly) {
  // 18 significant digits: more than a double holds exactly; the nearest double wins.
  Result r = decode_word("X+099", "123456789.123456789", kDs);
  ASSERT_TRUE(r.value);
  EXPECT_EQ(*r.value, std::strtod("123456789.123456789", nullptr));
  Result implied = decode_word("X+099", "123456789123456789", kImplied);
  ASSERT_TRUE(implied.value);
  EXPECT_EQ(*implied.value, std::strtod("123456789.123456789", nullptr));
}

TEST(Decode, NegativeZeroIsZero) {
  Result r = decode_word("X+053", "-0", kDs);
  ASSERT_TRUE(r.value);
  EXPECT_FALSE(std::signbit(*r.value));
}

}  // namespace
}  // namespace ncc::gost
