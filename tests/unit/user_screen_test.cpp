// The NC-110 user screen (video frame 8, §5.6): fields, widths, masks, the grid.
#include <gtest/gtest.h>

#include "devices/user_screen.h"

namespace ncc::screen {
namespace {

Content text(std::string s) { return {true, std::move(s), 0}; }
Content number(double v) { return {false, {}, v}; }

TEST(UserScreen, WidthsAndMasksOfEveryFormat) {
  // Table 5.3 (BY three wide, as its mask XXX), table 5.5.
  EXPECT_EQ(show_value(Format::Bool, 1, format_width(Format::Bool)), "1");
  EXPECT_EQ(show_value(Format::Byte, 255, format_width(Format::Byte)), "255");
  EXPECT_EQ(show_value(Format::Integer, -32768, format_width(Format::Integer)), "-32768");
  EXPECT_EQ(show_value(Format::Long, -12345678, format_width(Format::Long)), "-12345678");
  EXPECT_EQ(show_value(Format::Real, -12345.6789, format_width(Format::Real)), "-12345.6789");
  EXPECT_EQ(show_value(Format::LongReal, 0, 11), "0          ");
  EXPECT_EQ(show_value(Format::LongReal, 2.5, 11), "2.5        ");
  EXPECT_EQ(show_value(Format::LongReal, 1.00004, 11), "1          ");  // four decimals at most
  EXPECT_EQ(show_value(Format::LongReal, -0.00001, 11), "0          ");
  EXPECT_EQ(show_value(Format::LongReal, 99999.5, 11), "99999.5    ");
  EXPECT_EQ(show_value(Format::LongReal, 123456, 11), "***********");  // six digits: past the mask
  EXPECT_EQ(show_value(Format::Integer, 123456, 6), "******");
  EXPECT_EQ(show_value(Format::Byte, 1000, 3), "***");
  EXPECT_EQ(show_value(Format::Byte, -1, 3), "***");
}

// The fields of the manual's example (§5.6.2.3, figure 5.2), in Latin letters.
TEST(UserScreen, TheManualsExample) {
  UserScreen s;
  s.switch_on();
  EXPECT_EQ(s.define(1, 3, 10, text("SIZE X = "), std::nullopt, {}), "");
  EXPECT_EQ(s.define(2, 3, 19, number(0), Format::LongReal, {}), "");
  EXPECT_EQ(s.define(3, 4, 10, text("SIZE Z = "), std::nullopt, {}), "");
  EXPECT_EQ(s.define(4, 4, 19, number(0), Format::LongReal, {}), "");
  EXPECT_EQ(s.define(5, 5, 10, text("FEED = "), std::nullopt, {}), "");
  EXPECT_EQ(s.define(6, 5, 19, number(0), Format::Real, {}), "");
  EXPECT_EQ(s.lines()[2], "");  // DEF only defines
  EXPECT_EQ(s.show_all(), "");
  EXPECT_EQ(s.lines()[2], "         SIZE X = 0");
  EXPECT_EQ(s.lines()[3], "         SIZE Z = 0");
  EXPECT_EQ(s.lines()[4], "         FEED =   0");
  EXPECT_EQ(s.show_with(2, number(120.25)), "");
  EXPECT_EQ(s.lines()[2], "         SIZE X = 120.25");
  EXPECT_EQ(s.text(1), "SIZE X = ");
  EXPECT_EQ(s.text(2), std::nullopt);
  EXPECT_EQ(s.lines().size(), 20u);
}

TEST(UserScreen, TextsAreCharactersNotBytes) {
  UserScreen s;
  s.switch_on();
  ASSERT_EQ(s.define(1, 1, 1, text("Размер Х = "), std::nullopt, {}), "");
  ASSERT_EQ(s.define(2, 1, 12, number(7), std::nullopt, {}), "");  // IN: integral, six wide
  ASSERT_EQ(s.show_all(), "");
  EXPECT_EQ(s.lines()[0], "Размер Х = 7");
  EXPECT_EQ(s.rendered(2), "7     ");
}

TEST(UserScreen, WhatIsRefused) {
  UserScreen s;
  EXPECT_EQ(s.show_all(), "the user screen is off: (SCR,ON) first");
  EXPECT_EQ(s.define(1, 21, 1, number(0), std::nullopt, {}), "row 21 is not on the screen: rows are 1 to 20");
  EXPECT_EQ(s.define(1, 1, 65, number(0), std::nullopt, {}), "column 65 is not one a field starts at: 1 to 64");
  EXPECT_EQ(s.define(0, 1, 1, number(0), std::nullopt, {}), "field 0 does not exist: fields are numbered from 1");
  EXPECT_EQ(s.define(1, 1, 1, text("X"), Format::Integer, {}),
            "a text does not fit format 3 (IN): its format is 7 (CH)");
  EXPECT_EQ(s.define(1, 1, 1, number(1), Format::Chars, {}),
            "a number does not fit format 7 (CH): give its own format, 1 to 6");
  EXPECT_EQ(s.define(1, 1, 1, std::nullopt, std::nullopt, {}),
            "a field without an initial value needs a numeric format, 1 to 6");
  EXPECT_EQ(s.define(1, 1, 64, text(std::string(20, 'X')), std::nullopt, {}),
            "the field ends at column 83, past the screen's 78");
  s.switch_on();
  ASSERT_EQ(s.define(1, 1, 1, std::nullopt, Format::Byte, {}), "");
  EXPECT_EQ(s.show(2, false), "field 2 is not defined (DEF)");
  ASSERT_EQ(s.show(1, true), "");
  EXPECT_TRUE(s.attributes(1).inverse);
  EXPECT_EQ(s.define(1, 2, 1, number(0), std::nullopt, {}),
            "field 1 is on the screen: switch it off (SCR,OFF) to define it again");
  EXPECT_EQ(s.show_with(1, text("A")), "field 1 is of format 2 (BY): a number goes there, not a text");
  ASSERT_EQ(s.define(2, 2, 1, text("AB"), std::nullopt, {}), "");
  EXPECT_EQ(s.show_with(2, text("ABC")), "field 2 holds 2 characters, not 3");
  EXPECT_EQ(s.show_with(2, number(1)), "field 2 is of format 7 (CH): a text goes there, not a number");
  s.switch_off();
  EXPECT_EQ(s.show(1, false), "the user screen is off: (SCR,ON) first");
  s.switch_on();  // a clear screen without fields
  EXPECT_EQ(s.show(1, false), "field 1 is not defined (DEF)");
  EXPECT_EQ(s.lines()[0], "");
}

}  // namespace
}  // namespace ncc::screen
