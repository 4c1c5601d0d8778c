// The GOST front end and the table-driven checks, looked at through the IR they make,
// and the data they read: dialect tables and machine profiles.
#include <gtest/gtest.h>

#include "contract/word_slots.h"
#include "driver/pipeline.h"
#include "stdlib/tables.h"

namespace ncc {
namespace {

struct Read {
  Session s;
  std::optional<ir::Program> program;
  std::vector<std::string> codes;  // diagnostic codes in order of report

  explicit Read(std::string text, const std::string& profile = "") {
    if (!profile.empty()) {
      auto p = stdlib::Profile::parse(s.sources, "test.toml", profile, s.diags);
      EXPECT_TRUE(p);
      s.profile = std::move(*p);
    }
    program = analyse(s, s.sources.add("t.nc", std::move(text)), "gost");
    for (const Diagnostic& d : s.diags.all()) codes.push_back(diag_code(d.id));
  }
  const ir::Block& block(size_t unit, size_t index) const { return program->units.at(unit).blocks.at(index); }
  double value(const ir::Word& w) const { return program->exprs[w.value].number; }
};

TEST(IrAddress, HoldsEveryAddressAWordCanHave) {
  // The names of the word slots (NC-110 operands "#12", second words "R'") and the
  // three-letter codes (NC-110 settings take three letters only) fit a word's address.
  for (int slot = 0; slot < kWordSlots; ++slot) {
    const std::string name = slot_name(slot);
    EXPECT_LE(name.size(), ir::Address::kMax) << name;
    EXPECT_EQ(ir::Address(name), name);
  }
  ir::Address a = "R";
  a += "'";
  EXPECT_EQ(a, "R'");
  EXPECT_EQ(a.size(), 2u);
  EXPECT_EQ(a + "10", "R'10");
  EXPECT_EQ(fmt::format("{}", ir::Address("RPT")), "RPT");
}

TEST(Frontend, BlocksWordsAndStatements) {
  Read r("leader text\n%0001 (PART)\nN001 G90 G00 X-1.5 (GO) M03\n/N2 X1. / Y2.\n:3 M30\nafter\n");
  ASSERT_TRUE(r.program);
  ASSERT_EQ(r.program->units.size(), 1u);
  const ir::Unit& u = r.program->units[0];
  EXPECT_EQ(u.name, "%0001");
  EXPECT_EQ(u.title, "PART");
  EXPECT_TRUE(u.ends_information);
  ASSERT_EQ(u.blocks.size(), 3u);

  const ir::Block& b1 = r.block(0, 0);
  EXPECT_EQ(b1.number, 1u);
  EXPECT_EQ(b1.range.line, 3u);
  ASSERT_EQ(b1.words.size(), 5u);
  EXPECT_EQ(b1.words[1].kind, ir::WordKind::Code);
  EXPECT_EQ(r.program->semantics.codes[b1.words[1].code].name, "G90");
  EXPECT_EQ(b1.words[3].address, "X");
  EXPECT_DOUBLE_EQ(r.value(b1.words[3]), -1.5);
  EXPECT_EQ(b1.words[3].range.col, 14u);
  ASSERT_EQ(b1.stmts.size(), 2u);
  EXPECT_EQ(b1.stmts[0].kind, ir::StmtKind::Comment);
  EXPECT_EQ(b1.stmts[0].label, "GO");
  EXPECT_EQ(b1.stmts[1].kind, ir::StmtKind::Machine);

  const ir::Block& b2 = r.block(0, 1);
  EXPECT_TRUE(b2.skippable);
  EXPECT_FALSE(b2.words[1].optional);  // X1.
  EXPECT_TRUE(b2.words[2].optional);   // Y2. after the second '/'

  const ir::Block& b3 = r.block(0, 2);
  EXPECT_TRUE(b3.main_block);
  EXPECT_EQ(b3.number, 3u);
  // The main block lacks what resuming needs; the trailer after M30 is not read.
  EXPECT_EQ(r.codes, (std::vector<std::string>{"NC3008", "NC1007"}));
}

TEST(Frontend, ReportsEveryProblemOfABlock) {
  Read r("%1\nN1 G01 G02 X1. X2. M03 M05 G05 L1\nN2 M02\n");
  EXPECT_EQ(r.codes, (std::vector<std::string>{"NC2001", "NC3002", "NC3001", "NC3005", "NC3003"}));
}

TEST(Frontend, StopsAtTheEndOfEachProgram) {
  Read r("%1\nN1 X1.\nN2 M02\nignored\n%2\nN1 X2.\nN2 M30\n%3\n");
  ASSERT_TRUE(r.program);
  ASSERT_EQ(r.program->units.size(), 2u);
  EXPECT_EQ(r.program->units[1].name, "%2");
  EXPECT_EQ(r.codes, (std::vector<std::string>{"NC1007"}));
}

TEST(Frontend, ProfileDecidesTheFormat) {
  Read r("%1\nN0001 X1500 F15\nN0002 M02\n", "[gost]\nformat = \"% N04 G02 X+053 F031 M02 *\"\n");
  ASSERT_TRUE(r.program);
  EXPECT_TRUE(r.codes.empty());
  EXPECT_DOUBLE_EQ(r.value(r.block(0, 0).words[1]), 1.5);  // implied decimal point
  EXPECT_DOUBLE_EQ(r.value(r.block(0, 0).words[2]), 1.5);
}

TEST(Frontend, BadProfileStopsBeforeReading) {
  Read r("%1\nN1 M02\n", "[gost]\nangle_unit = 5\nmode = \"loud\"\n");
  EXPECT_FALSE(r.program);
  EXPECT_EQ(r.codes, (std::vector<std::string>{"NC6004", "NC6004"}));
}

TEST(Frontend, IrPrintIsStable) {
  Read r("%7\nN1 G91 X1. (A)\nN2 M02\n");
  std::string text = ir::print(*r.program, r.s.sources);
  EXPECT_NE(text.find("unit program %7 @t.nc:1:1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  block @2:1 N1\n    words N1 G91 X1.\n    comment \"A\"\n    machine G91 X=1\n"),
            std::string::npos)
      << text;
}

TEST(Tables, GostTablesLoadCompletely) {
  Diagnostics diags;
  stdlib::DialectTables t = stdlib::load_dialect_tables("gost", diags);
  EXPECT_TRUE(diags.all().empty());
  EXPECT_EQ(t.addresses.size(), 26u);  // Table 1
  EXPECT_EQ(t.g_codes.size(), 45u);    // Table 4 without the codes it leaves undefined
  EXPECT_EQ(t.m_codes.size(), 18u);    // Table 7
  EXPECT_EQ(t.cycles.size(), 9u);      // Table 6
  EXPECT_EQ(t.power_on.size(), 3u);    // §8
  const stdlib::CodeEntry& m05 = t.m_codes.at(5);
  EXPECT_EQ(m05.desc.timing, Timing::After);
  EXPECT_EQ(m05.desc.calls, (std::vector<FnCall>{{Fn::SpindleStop}, {Fn::CoolantOff}}));
  EXPECT_EQ(t.g_codes.at(53).desc.scope, Scope::Block);
  EXPECT_EQ(t.g_codes.at(84).desc.calls, (std::vector<FnCall>{{Fn::Cycle, 3}}));
}

TEST(Tables, BadRowsAreReported) {
  Diagnostics diags;
  std::map<int, stdlib::CodeEntry> codes;
  auto table = stdlib::parse_table("x.tsv",
                                   "G05 a modal motion.rapid \"ok\"\nG06 a sometimes motion.rapid \"\"\n"
                                   "G07 a modal warp.speed \"\"\nG08 a modal\n",
                                   5, diags);
  stdlib::read_code_table(table, 'G', {}, codes, diags);
  EXPECT_EQ(codes.size(), 1u);
  ASSERT_EQ(diags.all().size(), 3u);
  EXPECT_NE(diags.all()[0].message.find("x.tsv:4: expected 5 columns"), std::string::npos);
  EXPECT_NE(diags.all()[1].message.find("x.tsv:2: scope"), std::string::npos);
  EXPECT_NE(diags.all()[2].message.find("unknown function 'warp.speed'"), std::string::npos);
}

TEST(Tables, BlockOnlyCodesMustBeRestorable) {
  Diagnostics diags;
  std::map<int, stdlib::CodeEntry> codes;
  auto table = stdlib::parse_table("m.tsv",
                                   "M70 before block - coolant.flood \"flood for one block\"\n"
                                   "M71 before block - spindle.cw \"spindle for one block\"\n",
                                   6, diags);
  stdlib::read_code_table(table, 'M', {}, codes, diags);
  EXPECT_EQ(codes.size(), 1u);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_NE(diags.all()[0].message.find("m.tsv:1: a block-only code cannot switch coolant"), std::string::npos);
}

TEST(Profile, NumbersMustBeFinite) {
  SourceManager sources;
  Diagnostics diags;
  auto p = stdlib::Profile::parse(sources, "m.toml",
                                  "[gost]\narc_tolerance = inf\n[machine]\ninitial_position = { Y = nan }\n", diags);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->number("gost.arc_tolerance", diags));
  stdlib::load_machine_config(*p, diags);
  ASSERT_EQ(diags.all().size(), 2u);
  EXPECT_NE(diags.all()[0].message.find("must be a finite number"), std::string::npos);
}

TEST(Profile, FallsBackToTheDefaultAndReportsTypos) {
  SourceManager sources;
  Diagnostics diags;
  auto p = stdlib::Profile::parse(sources, "m.toml", "[gost]\narc_tolerance = 0.01\narc_tolerence = 1\n", diags);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->number("gost.arc_tolerance", diags), 0.01);
  EXPECT_EQ(p->string("gost.dwell_address", diags), "P");  // from the default
  EXPECT_TRUE(p->user_sets("gost.arc_tolerance"));
  EXPECT_FALSE(p->user_sets("gost.dwell_address"));
  p->report_unused(diags);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].id, DiagId::ProfileUnknownKey);
  EXPECT_EQ(diags.all()[0].range.line, 3u);
}

TEST(Profile, MachineDataReplacesTheDefaultCollections) {
  SourceManager sources;
  Diagnostics diags;
  auto p = stdlib::Profile::parse(sources, "m.toml", "[offsets]\n7 = { length = 50.0, radius = 3.0 }\n", diags);
  ASSERT_TRUE(p);
  MachineConfig m = stdlib::load_machine_config(*p, diags);
  EXPECT_TRUE(diags.all().empty());
  ASSERT_EQ(m.offsets.size(), 1u);
  EXPECT_EQ(m.offsets.at(7).radius, 3.0);
  EXPECT_EQ(m.tools.size(), 3u);  // not given: the default's
}

}  // namespace
}  // namespace ncc
