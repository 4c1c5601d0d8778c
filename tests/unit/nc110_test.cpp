// The NC-110 front end, looked at through the IR it makes, and its tables: what the
// golden tests do not show directly (slots, expression trees, table contents).
#include <gtest/gtest.h>

#include "driver/pipeline.h"
#include "stdlib/tables.h"

namespace ncc {
namespace {

struct Read {
  Session s;
  std::optional<ir::Program> program;
  std::vector<std::string> codes;  // diagnostic codes in order of report

  explicit Read(std::string text) {
    program = analyse(s, s.sources.add("t.nc", std::move(text)), "nc110");
    for (const Diagnostic& d : s.diags.all()) codes.push_back(diag_code(d.id));
  }
  const ir::Block& block(size_t index) const { return program->units.at(0).blocks.at(index); }
  std::string expr(ir::ExprId id) const { return ir::print_expr(*program, id); }
};

TEST(Nc110Tables, LoadWithoutProblems) {
  Diagnostics diags;
  stdlib::DialectTables t = stdlib::load_dialect_tables("nc110", diags);
  for (const Diagnostic& d : diags.all()) ADD_FAILURE() << d.message;
  EXPECT_EQ(t.g_codes.size(), 42u);  // Table 2.2
  EXPECT_EQ(t.m_codes.size(), 24u);  // Table 2.3
  EXPECT_EQ(t.cycles.size(), 7u);    // Table 2.6: G81-G86, G89
  EXPECT_EQ(t.addresses.at('M').max_count, 4);
  EXPECT_EQ(t.addresses.at('R').repeat, stdlib::Repeat::Twice);
  EXPECT_EQ(t.addresses.at('u').word_class, stdlib::WordClass::Factor);
  EXPECT_EQ(t.addresses.at('F').decimals, 2);
  EXPECT_DOUBLE_EQ(t.addresses.at('F').min, 0.01);
}

TEST(Nc110Tables, CompatibilityIsEitherCellOrOneClass) {
  Diagnostics diags;
  stdlib::DialectTables t = stdlib::load_dialect_tables("nc110", diags);
  auto incompatible = [&](int a, int b) { return stdlib::has_pair(t.incompatible, a, b); };
  // G01's row admits G72, G72's row excludes G01: one cell is enough, both orders.
  EXPECT_TRUE(incompatible(1, 72));
  EXPECT_TRUE(incompatible(72, 1));
  // G04 and G33: only G04's row says so.
  EXPECT_TRUE(incompatible(33, 4));
  // One class of Table 2.5 (the table has no cells for G93/G94/G95).
  EXPECT_TRUE(incompatible(93, 95));
  EXPECT_TRUE(incompatible(96, 97));
  // G95 gets its classmates' row: not with G17.
  EXPECT_TRUE(incompatible(95, 17));
  // Compatible: G90 with G01, G81 with G00.
  EXPECT_FALSE(incompatible(90, 1));
  EXPECT_FALSE(incompatible(81, 0));
}

TEST(Nc110Frontend, WordsGoToTheirSlots) {
  Read r("N5 G1 X10 Y Z-2.5 F100 T3.12 R5 R-2\n");
  ASSERT_TRUE(r.program);
  const ir::Block& b = r.block(0);
  EXPECT_EQ(b.number, 5u);
  std::map<std::string, std::pair<int, std::string>> words;
  for (const ir::Word& w : b.words)
    if (w.kind == ir::WordKind::Parameter) words[slot_name(w.slot)] = {w.slot, r.expr(w.value)};
  EXPECT_EQ(words.at("Y").second, "0");    // a bare address is zero
  EXPECT_EQ(words.at("T").second, "3");    // tool
  EXPECT_EQ(words.at("T'").second, "12");  // corrector
  EXPECT_EQ(words.at("R").second, "5");    // R1
  EXPECT_EQ(words.at("R'").second, "-2");  // R2
}

TEST(Nc110Frontend, ExpressionsFollowPrecedence) {
  Read r("E37=E31*SIN(E30)+123.4567/SQR(16)\nE1=8/4/2\nE2=-2-3\nE30=MOD(E31,NEG(E32))\n");
  ASSERT_TRUE(r.program);
  EXPECT_TRUE(r.codes.empty());
  EXPECT_EQ(r.expr(r.block(0).stmts[0].value), "(+ (* E31 (sin E30)) (/ 123.4567 (sqrt 16)))");
  EXPECT_EQ(r.expr(r.block(1).stmts[0].value), "(/ (/ 8 4) 2)");
  EXPECT_EQ(r.expr(r.block(2).stmts[0].value), "(- -2 3)");
  EXPECT_EQ(r.expr(r.block(3).stmts[0].value), "(mod E31 (neg E32))");
}

TEST(Nc110Frontend, MemoryReferencesAndTexts) {
  Read r("SA12=SK.BL\nSK7.3CH=\"RI\"\nE35=SYVAR2.LR\nSYVAR 1.4CH = SK7.4CH\n");
  ASSERT_TRUE(r.program);
  EXPECT_TRUE(r.codes.empty());
  EXPECT_EQ(r.expr(r.block(0).stmts[0].target), "SA[12].BL");
  EXPECT_EQ(r.expr(r.block(0).stmts[0].value), "SK[0].BL");
  EXPECT_EQ(r.expr(r.block(1).stmts[0].target), "SK[7].3CH");
  EXPECT_EQ(r.expr(r.block(1).stmts[0].value), "\"RI \"");  // padded to 3
  EXPECT_EQ(r.expr(r.block(2).stmts[0].value), "SYVAR[2].LR");
  EXPECT_EQ(r.expr(r.block(3).stmts[0].value), "SK[7].4CH");
}

TEST(Nc110Frontend, ThreeLetterCodesBecomeCodesWithOperandWords) {
  Read r("(UOT,1,X-50,YE31)\n(DLO,X-300 X300)\n(DPI,Z,X)\n");
  ASSERT_TRUE(r.program);
  EXPECT_TRUE(r.codes.empty()) << r.codes[0];
  auto words = [&](size_t i) {
    std::string s;
    for (const ir::Word& w : r.block(i).words)
      if (w.kind == ir::WordKind::Code)
        s += w.address + ":";
      else
        s += (s.back() == ':' ? "" : " ") + slot_name(w.slot) + "=" + r.expr(w.value);
    return s;
  };
  EXPECT_EQ(words(0), "UOT:#1=1 X=-50 Y=E31");
  EXPECT_EQ(words(1), "DLO:X=-300 X'=300");
  EXPECT_EQ(words(2), "DPI:#1=2 #2=0");  // axis numbers: Z, X
}

TEST(Nc110Frontend, FlowStatements) {
  Read r("(RPT,E5)\n\"A\" E1=1\n(ERP)\n(EPP,A,A)\n(BGT,E1,0.5,A)\n(BNE,SYVAR1.2CH,\"OK\",A)\n");
  ASSERT_TRUE(r.program);
  EXPECT_EQ(r.block(0).stmts[0].kind, ir::StmtKind::RepeatBegin);
  EXPECT_DOUBLE_EQ(r.block(0).stmts[0].limit, 99);
  EXPECT_EQ(r.block(3).stmts[0].kind, ir::StmtKind::CallRange);
  EXPECT_EQ(r.expr(r.block(4).stmts[0].cond), "(> E1 0.5)");
  EXPECT_EQ(r.expr(r.block(5).stmts[0].cond), "(not (text== SYVAR[1].2CH \"OK\"))");
  // A jump into the loop's body from outside it.
  ASSERT_EQ(r.codes.size(), 3u);
  EXPECT_EQ(r.codes[0], "NC3023");
}

}  // namespace
}  // namespace ncc
