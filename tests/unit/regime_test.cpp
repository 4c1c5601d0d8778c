// Cutting conditions (sim/regime.h): the formulas against values worked by hand, the
// machine limits, the reference table stdlib/cutting_data.tsv and its checks.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "sim/regime.h"
#include "stdlib/embedded.h"

namespace ncc::sim {
namespace {

// n = 1000 * 100 / (pi * 10) = 10000 / pi = 3183.0989 rpm.
TEST(Regime, SpindleSpeedFromCuttingSpeed) {
  EXPECT_NEAR(spindle_speed(100, 10), 3183.0989, 1e-4);
  EXPECT_NEAR(spindle_speed(25, 8), 994.7184, 1e-4);  // 25000 / (8 pi)
  EXPECT_NEAR(cutting_speed(3183.0989, 10), 100, 1e-4);
}

// Vf = fz z n = 0.06 * 4 * 3183.0989 = 763.94 mm/min; the block takes S3183 and
// F = 0.24 * 3183 = 763.92, so F764.
TEST(Regime, MillingFeedAndBlock) {
  RegimeInput in{.diameter = 10, .teeth = 4, .vc = 100, .feed = 0.06};
  const Regime r = compute_regime(in);
  EXPECT_NEAR(r.rpm, 3183.0989, 1e-4);
  EXPECT_NEAR(r.feed_rate, 763.9437, 1e-4);
  EXPECT_FALSE(r.rpm_clamped);
  EXPECT_FALSE(r.feed_clamped);
  const BlockWords w = block_words(r, in, false);
  EXPECT_EQ(w.s, 3183);
  EXPECT_EQ(w.f, 764);
  EXPECT_EQ(w.text, "S3183 M3 F764");
}

// A drill's feed is per revolution: Vf = f n = 0.1 * 994.7184 = 99.47 mm/min.
TEST(Regime, DrillingFeedPerRevolution) {
  RegimeInput in{.diameter = 8, .teeth = 1, .vc = 25, .feed = 0.1};
  const Regime r = compute_regime(in);
  EXPECT_NEAR(r.feed_rate, 99.4718, 1e-4);
  EXPECT_EQ(block_words(r, in, false).text, "S995 M3 F100");  // 0.1 * 995 = 99.5 -> 100
}

// D 6, Vc 300: n = 300000 / (6 pi) = 15915.49 over a limit of 8000. The spindle runs
// at 8000, Vc falls to 6 pi 8 = 150.80 m/min, the feed follows: 0.05 * 3 * 8000 = 1200.
TEST(Regime, MaxRpmClampsAndTheFeedFollows) {
  RegimeInput in{.diameter = 6, .teeth = 3, .vc = 300, .feed = 0.05, .max_rpm = 8000};
  const Regime r = compute_regime(in);
  EXPECT_TRUE(r.rpm_clamped);
  EXPECT_NEAR(r.rpm_wanted, 15915.494, 1e-3);
  EXPECT_EQ(r.rpm, 8000);
  EXPECT_NEAR(r.vc, 150.796, 1e-3);
  EXPECT_NEAR(r.feed_rate, 1200, 1e-9);
  EXPECT_NEAR(r.feed, 0.05, 1e-12);
  EXPECT_FALSE(r.feed_clamped);
  EXPECT_EQ(block_words(r, in, false).text, "S8000 M3 F1200");
}

// 763.94 mm/min over a limit of 500: Vf 500, fz = 500 / (4 * 3183.0989) = 0.039270.
TEST(Regime, MaxFeedClampsAndTheFeedPerToothFollows) {
  RegimeInput in{.diameter = 10, .teeth = 4, .vc = 100, .feed = 0.06, .max_feed = 500};
  const Regime r = compute_regime(in);
  EXPECT_FALSE(r.rpm_clamped);
  EXPECT_TRUE(r.feed_clamped);
  EXPECT_NEAR(r.feed_wanted, 763.9437, 1e-4);
  EXPECT_EQ(r.feed_rate, 500);
  EXPECT_NEAR(r.feed, 0.0392699, 1e-7);
  EXPECT_EQ(block_words(r, in, false).text, "S3183 M3 F500");  // 0.0392699 * 4 * 3183 = 499.99
}

// Both limits: n clamped first, then the feed at the clamped n.
TEST(Regime, BothLimits) {
  RegimeInput in{.diameter = 6, .teeth = 3, .vc = 300, .feed = 0.05, .max_rpm = 8000, .max_feed = 1000};
  const Regime r = compute_regime(in);
  EXPECT_TRUE(r.rpm_clamped);
  EXPECT_TRUE(r.feed_clamped);
  EXPECT_NEAR(r.feed_wanted, 1200, 1e-9);
  EXPECT_NEAR(r.feed, 1000.0 / 24000, 1e-12);
  EXPECT_EQ(block_words(r, in, false).text, "S8000 M3 F1000");
}

// 1/2 in, 300 SFM: n = 12 * 300 / (pi * 0.5) = 2291.83 rpm; 2 teeth at 0.002 in:
// Vf = 0.004 * 2291.83 = 9.167 in/min; at S2292, 9.168 -> F9.2.
TEST(Regime, InchBlock) {
  RegimeInput in{.diameter = 12.7, .teeth = 2, .vc = 300 * 0.3048, .feed = 0.002 * 25.4};
  const Regime r = compute_regime(in);
  EXPECT_NEAR(r.rpm, 2291.831, 1e-3);
  EXPECT_NEAR(r.feed_rate / 25.4, 9.1673, 1e-4);
  EXPECT_EQ(block_words(r, in, true).text, "S2292 M3 F9.2");
}

TEST(RegimeTable, LoadsWithoutErrors) {
  std::vector<std::string> errors;
  const CuttingTable t = load_cutting_table(errors);
  for (const std::string& e : errors) ADD_FAILURE() << e;
  std::set<std::string> materials, tools;
  for (const auto& m : t.materials) materials.insert(m.key);
  for (const auto& k : t.tools) tools.insert(k.key);
  EXPECT_EQ(materials, (std::set<std::string>{"structural_steel", "alloy_steel", "stainless_steel", "grey_cast_iron",
                                              "aluminium", "brass", "titanium", "plastics"}));
  EXPECT_EQ(tools, (std::set<std::string>{"hss_endmill", "carbide_endmill", "carbide_facemill", "hss_drill",
                                          "carbide_drill"}));
  EXPECT_EQ(t.rows.size(), 86u);
  EXPECT_EQ(t.tool("hss_drill")->feed_per, FeedPer::Revolution);
  EXPECT_EQ(t.tool("carbide_facemill")->feed_per, FeedPer::Tooth);
}

// Every row is sane: positive, min <= max, feeds that fit the tool kind; every
// material and tool kind has rows; every source is explained in the file's header.
TEST(RegimeTable, EveryRowIsSane) {
  std::vector<std::string> errors;
  const CuttingTable t = load_cutting_table(errors);
  const std::string_view text = *stdlib::embedded_file("cutting_data.tsv");
  for (const CuttingRow& r : t.rows) {
    SCOPED_TRACE(testing::Message() << "cutting_data.tsv:" << r.line);
    EXPECT_GE(r.d_min, 0);
    EXPECT_LE(r.d_min, r.d_max);
    EXPECT_GT(r.vc_min, 0);
    EXPECT_LE(r.vc_min, r.vc_max);
    EXPECT_LE(r.vc_max, 1000);  // m/min: no tool kind here cuts faster
    if (r.has_feed) {
      EXPECT_GT(r.f_min, 0);
      EXPECT_LE(r.f_min, r.f_max);
      EXPECT_LT(r.f_max, 1);  // mm per tooth or revolution
    }
    ASSERT_NE(t.source(r.source), nullptr);
    EXPECT_FALSE(r.note.empty());
  }
  for (const auto& m : t.materials) {
    bool any = false;
    for (const auto& k : t.tools) any = any || !t.rows_for(k.key, m.key).empty();
    EXPECT_TRUE(any) << m.key;
  }
  for (const auto& k : t.tools) {
    bool any = false;
    for (const auto& m : t.materials) any = any || !t.rows_for(k.key, m.key).empty();
    EXPECT_TRUE(any) << k.key;
  }
  for (const auto& s : t.sources)
    EXPECT_NE(text.find("#   " + s.key + " "), std::string_view::npos) << s.key << " is not explained in the header";
}

TEST(RegimeTable, ReferenceInARowBetweenRowsAndOutside) {
  std::vector<std::string> errors;
  const CuttingTable t = load_cutting_table(errors);
  // Tungaloy, carbon steel, ø10-ø12: Vc 140-180, fz 0.035-0.055.
  auto in_row = t.reference("carbide_endmill", "structural_steel", 10);
  ASSERT_TRUE(in_row);
  EXPECT_EQ(in_row->how, Reference::How::Row);
  EXPECT_EQ(in_row->vc_min, 140);
  EXPECT_EQ(in_row->vc_max, 180);
  EXPECT_EQ(in_row->f_min, 0.035);
  EXPECT_EQ(in_row->f_max, 0.055);
  EXPECT_EQ(in_row->source, "TUNG");
  // D 9: halfway between ø8 (0.03-0.045) and ø10 (0.035-0.055).
  auto between = t.reference("Carbide-EndMill", "STRUCTURAL_STEEL", 9);
  ASSERT_TRUE(between);
  EXPECT_EQ(between->how, Reference::How::Interpolated);
  EXPECT_NEAR(between->f_min, 0.0325, 1e-12);
  EXPECT_NEAR(between->f_max, 0.05, 1e-12);
  EXPECT_EQ(between->below->d_max, 8);
  EXPECT_EQ(between->above->d_min, 10);
  // D 32: above the last row, ø16-ø20.
  auto outside = t.reference("carbide_endmill", "structural_steel", 32);
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->how, Reference::How::Nearest);
  EXPECT_EQ(outside->f_max, 0.07);
  // An open band holds any larger drill.
  auto open = t.reference("hss_drill", "alloy_steel", 40);
  ASSERT_TRUE(open);
  EXPECT_EQ(open->how, Reference::How::Row);
  EXPECT_EQ(open->f_max, 0.635);
  // A source with a speed only; a pair the table does not hold.
  auto speed_only = t.reference("hss_endmill", "aluminium", 12);
  ASSERT_TRUE(speed_only);
  EXPECT_FALSE(speed_only->has_feed);
  EXPECT_FALSE(t.reference("hss_drill", "titanium", 10));
}

TEST(RegimeTable, BadRowsAreReportedWithTheirLines) {
  const char* text = R"(material steel "steel"
material steel "again"
tool mill per_tooth "a mill"
tool drill per_minute "a drill"
source S "a source"
cut mill steel 6 8 180 140 0.03 0.04 S
cut mill steel 6 8 140 180 0.05 0.04 S
cut mill steel 6 8 140 180 -0.01 0.04 S
cut mill wood 6 8 140 180 0.03 0.04 S
cut mill steel 6 8 140 180 0.03 0.04 X
cut mill steel 10 12 140 180 0.03 0.04 S
cut mill steel 11 14 140 180 0.03 0.04 S
row mill x
cut mill steel 20 16 140 180 0.03 0.04 S
short row
)";
  std::vector<std::string> errors;
  const CuttingTable t = parse_cutting_table("t.tsv", text, errors);
  const std::vector<std::string> expected = {
      "t.tsv:2: material 'steel' is defined twice",
      "t.tsv:4: a tool row is: tool KEY per_tooth|per_rev \"text\"",
      "t.tsv:6: the cutting speeds must be positive, VC_MIN <= VC_MAX",
      "t.tsv:7: the feeds must be positive, F_MIN <= F_MAX (or both \"-\")",
      "t.tsv:8: the feeds must be positive, F_MIN <= F_MAX (or both \"-\")",
      "t.tsv:9: unknown material 'wood'",
      "t.tsv:10: unknown source 'X'",
      "t.tsv:12: its diameters overlap the row on line 11",
      "t.tsv:13: unknown row kind 'row' (material, tool, source, cut)",
      "t.tsv:14: the diameters must be D_MIN <= D_MAX, not negative (\"-\": no bound)",
      "t.tsv:15: expected 3 to 11 columns, found 2",
  };
  EXPECT_EQ(errors, expected);
  EXPECT_EQ(t.rows.size(), 2u);  // lines 11 and 12: an overlap is reported, not dropped
}

}  // namespace
}  // namespace ncc::sim
