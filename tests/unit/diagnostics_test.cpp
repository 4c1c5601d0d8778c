// Diagnostics: the catalogue, the printers and the collector.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/diagnostics.h"

namespace ncc {
namespace {

TEST(Diagnostics, CodesAreUniqueAndDocumented) {
  std::ifstream in(NCC_TEST_DATA "/../docs/diagnostics.md");
  std::stringstream doc;
  doc << in.rdbuf();
  std::set<uint16_t> numbers;
  std::set<std::string_view> names;
  for (uint16_t i = 0; i < static_cast<uint16_t>(DiagId::Count); ++i) {
    const DiagInfo& d = diag_info(static_cast<DiagId>(i));
    EXPECT_TRUE(numbers.insert(d.number).second) << d.number;
    EXPECT_TRUE(names.insert(d.name).second) << d.name;
    EXPECT_EQ(diag_by_name(d.name), d.id);
    // docs/diagnostics.md lists every entry as the catalogue has it.
    std::string row = fmt::format("| {} | `{}` |", diag_code(d.id), d.name);
    EXPECT_NE(doc.str().find(row), std::string::npos) << "docs/diagnostics.md lacks " << row;
  }
}

// A DiagId converts to the parameter of diag_message() and report() only in a constant
// expression that finds the message's placeholders fit the arguments. Made in a template
// argument, a conversion that does not fit is a substitution failure a concept sees.
template <DiagId id, typename... Args>
concept ReportableWith = requires {
  typename std::integral_constant<DiagId, DiagIdFor<Args...>(id).id()>;
};

// "{0} appears more than {1} in the block"
static_assert(ReportableWith<DiagId::WordRepeated, std::string, const char*>);
static_assert(!ReportableWith<DiagId::WordRepeated, std::string>);
static_assert(!ReportableWith<DiagId::WordRepeated, std::string, const char*, int>);
static_assert(ReportableWith<DiagId::DivisionByZero>);
static_assert(!ReportableWith<DiagId::DivisionByZero, int>);
// "'{0}' is corrupt: checksum {1:08x} does not match its contents ({2:08x})": x takes an integer.
static_assert(ReportableWith<DiagId::BytecodeChecksum, std::string, uint32_t, uint32_t>);
static_assert(!ReportableWith<DiagId::BytecodeChecksum, std::string, std::string, uint32_t>);
// Every function taking a DiagId and arguments takes the checked one.
static_assert(std::is_same_v<decltype(&diag_message<int>), std::string (*)(CheckedDiagId<int>, const int&)>);
static_assert(std::is_same_v<decltype(&Diagnostics::report<int>),
                             Diagnostic* (Diagnostics::*)(CheckedDiagId<int>, SourceRange, const int&)>);

static_assert(diag_check::placeholders("{1} before {0}").count == 2);
static_assert(diag_check::placeholders("{0} twice {0}").count == 1);
static_assert(diag_check::placeholders("{} and {}").count == 2);
static_assert(diag_check::placeholders("{{0}} is text").count == 0);
static_assert(diag_check::placeholders("{0} and {2}").malformed);  // {1}: an argument no placeholder shows
static_assert(diag_check::placeholders("{0").malformed);
static_assert(diag_check::placeholders("0}").malformed);
static_assert(diag_check::placeholders("{} and {1}").malformed);

TEST(Diagnostics, RuntimeIdIsCheckedWhenTheMessageIsMade) {
  volatile DiagId chosen = DiagId::WordRepeated;  // known only at run time
  EXPECT_EQ(diag_message(runtime_diag(chosen), "X", "once"), "X appears more than once in the block");
  EXPECT_EQ(diag_message(runtime_diag(chosen), "X"),
            "internal error: the arguments of NC3001 do not fit its message: 1 given, 2 taken");
}

TEST(Diagnostics, TextHasLocationCodeLineAndCaret) {
  SourceManager sources;
  uint32_t f = sources.add("p.nc", "%1\nN1 X10 X20\n");
  Diagnostics diags;
  Diagnostic* d = diags.report(DiagId::WordRepeated, {f, 2, 8, 2, 11}, "X", "once");
  d->notes.push_back({{f, 2, 4, 2, 7}, "X10 is here"});
  EXPECT_EQ(format_text(*d, sources),
            "p.nc:2:8: error: X appears more than once in the block [NC3001]\n"
            "    2 | N1 X10 X20\n"
            "      |        ^~~\n"
            "p.nc:2:4: note: X10 is here\n"
            "    2 | N1 X10 X20\n"
            "      |    ^~~\n");
}

TEST(Diagnostics, CaretCountsCharactersNotBytes) {
  SourceManager sources;
  uint32_t f = sources.add("p.nc", "(ДЕТАЛЬ) X\x01\n");
  Diagnostics diags;
  // The control byte is at byte column 17 but display column 11.
  Diagnostic* d = diags.report(DiagId::CharInvalid, {f, 1, 17, 1, 18}, "control character 0x01");
  std::string text = format_text(*d, sources);
  EXPECT_NE(text.find("    1 | (ДЕТАЛЬ) X \n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n      | " + std::string(10, ' ') + "^\n"), std::string::npos) << text;
}

TEST(Diagnostics, LongLinesAreCutAroundTheColumn) {
  SourceManager sources;
  std::string line(5000, 'X');
  uint32_t f = sources.add("p.nc", line + "\n");
  Diagnostics diags;
  Diagnostic* d = diags.report(DiagId::SyntaxError, {f, 1, 4000, 1, 4001}, "'X'");
  std::string text = format_text(*d, sources);
  EXPECT_LT(text.size(), 400u);
  EXPECT_NE(text.find("..."), std::string::npos);
}

TEST(Diagnostics, CitationIsAppended) {
  Diagnostics diags;
  diags.set_citations({{DiagId::ThreadFeed, "GOST 20999 §7.3"}});
  Diagnostic* d = diags.report(DiagId::ThreadFeed, {}, "G33");
  EXPECT_EQ(d->message, "F must not be programmed in a thread block G33: the pitch sets the feed (GOST 20999 §7.3)");
}

TEST(Diagnostics, ErrorLimitStopsWithOneMessage) {
  Diagnostics diags(2);
  for (int i = 0; i < 5; ++i) diags.report(DiagId::NoDigits, {}, "X");
  diags.report(DiagId::StrayRightParen, {});
  ASSERT_EQ(diags.all().size(), 4u);  // two errors, the limit notice, the warning
  EXPECT_EQ(diags.all()[2].id, DiagId::TooManyErrors);
  EXPECT_TRUE(diags.limit_reached());
}

TEST(Diagnostics, JsonEscapes) {
  EXPECT_EQ(json_escape("a\"b\\c\nd\x01"), "a\\\"b\\\\c\\nd\\u0001");
  SourceManager sources;
  uint32_t f = sources.add("p\"q.nc", "X\n");
  Diagnostics diags;
  diags.report(DiagId::NoDigits, {f, 1, 1, 1, 2}, "X");
  EXPECT_EQ(
      format_all(diags.all(), sources, DiagFormat::Json),
      R"({"code":"NC2002","name":"no-digits","severity":"error","message":"word X has no digits; a value of zero is written with at least one zero","range":{"file":"p\"q.nc","line":1,"column":1,"end_line":1,"end_column":2},"notes":[]})"
      "\n");
}

TEST(Diagnostics, SarifNamesRulesAndResults) {
  SourceManager sources;
  uint32_t f = sources.add("p.nc", "X\n");
  Diagnostics diags;
  diags.report(DiagId::NoDigits, {f, 1, 1, 1, 2}, "X");
  diags.report(DiagId::StrayRightParen, {f, 1, 1, 1, 2});
  std::string s = format_all(diags.all(), sources, DiagFormat::Sarif);
  EXPECT_NE(s.find(R"("version":"2.1.0")"), std::string::npos);
  EXPECT_NE(s.find(R"({"id":"NC2002","name":"no-digits"})"), std::string::npos);
  EXPECT_NE(s.find(R"("ruleId":"NC1005","level":"warning")"), std::string::npos);
  EXPECT_NE(s.find(R"("region":{"startLine":1,"startColumn":1,"endLine":1,"endColumn":2})"), std::string::npos);
}

}  // namespace
}  // namespace ncc
