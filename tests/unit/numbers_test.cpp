// whole_in: the one conversion of a program's double to an integer (support/numbers.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "support/numbers.h"

namespace ncc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(WholeIn, WholeNumbersInTheRange) {
  EXPECT_EQ(whole_in<uint32_t>(0, 0, 999), 0u);
  EXPECT_EQ(whole_in<uint32_t>(999, 0, 999), 999u);
  EXPECT_EQ(whole_in<uint32_t>(-0.0, 0, 999), 0u);
  EXPECT_EQ(whole_in<int>(-5, -9, 9), -5);
  EXPECT_EQ(whole_in<int>(1e9, 0, 2147483647), 1000000000);
}

TEST(WholeIn, NothingOutsideTheRange) {
  EXPECT_EQ(whole_in<uint32_t>(1000, 0, 999), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(-1, 0, 999), std::nullopt);
  EXPECT_EQ(whole_in<int>(-10, -9, 9), std::nullopt);
}

TEST(WholeIn, NothingForFractionsNaNsAndInfinities) {
  EXPECT_EQ(whole_in<uint32_t>(1.5, 0, 999), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(0.999999999, 0, 999), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(kNaN, 0, 999), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(kInf, 0, UINT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<int64_t>(-kInf, INT64_MIN, INT64_MAX), std::nullopt);
}

// The values of the issue: they wrapped to #3001 and #1 (4294967297 = 2^32 + 1).
TEST(WholeIn, NoWrapAtTheTypesEnds) {
  EXPECT_EQ(whole_in<uint32_t>(4294970297, 0, UINT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(4294967297, 0, UINT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(4294967296, 0, UINT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<uint32_t>(4294967295, 0, UINT32_MAX), UINT32_MAX);
  EXPECT_EQ(whole_in<uint32_t>(1e10, 0, UINT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<int32_t>(2147483648.0, INT32_MIN, INT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<int32_t>(-2147483648.0, INT32_MIN, INT32_MAX), INT32_MIN);
  EXPECT_EQ(whole_in<int32_t>(-2147483649.0, INT32_MIN, INT32_MAX), std::nullopt);
  EXPECT_EQ(whole_in<uint8_t>(256, 0, 255), std::nullopt);
  EXPECT_EQ(whole_in<uint8_t>(255, 0, 255), 255);
  EXPECT_EQ(whole_in<int16_t>(-32769, INT16_MIN, INT16_MAX), std::nullopt);
}

// 64 bits: the largest doubles below 2^63 and 2^64 fit, 2^63 and 2^64 do not (the
// double nearest INT64_MAX is 2^63, which a naive `v <= hi` would let through).
TEST(WholeIn, SixtyFourBits) {
  EXPECT_EQ(whole_in<int64_t>(9223372036854775807.0, INT64_MIN, INT64_MAX), std::nullopt);
  EXPECT_EQ(whole_in<int64_t>(9223372036854774784.0, INT64_MIN, INT64_MAX), 9223372036854774784);
  EXPECT_EQ(whole_in<int64_t>(-9223372036854775808.0, INT64_MIN, INT64_MAX), INT64_MIN);
  EXPECT_EQ(whole_in<uint64_t>(18446744073709551615.0, 0, UINT64_MAX), std::nullopt);
  EXPECT_EQ(whole_in<uint64_t>(18446744073709549568.0, 0, UINT64_MAX), 18446744073709549568u);
  EXPECT_EQ(whole_in<uint64_t>(1e300, 0, UINT64_MAX), std::nullopt);
}

}  // namespace
}  // namespace ncc
