// tests/fixed/unit_test.cpp — hand-checked cases of include/fixed: boundary values, the widths of
// the integer datapath types, fixed_point conversions, numeric_limits, hashing and printing. Every
// expected value below is worked out by hand in the comment next to it.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <sstream>
#include <type_traits>
#include <unordered_set>

#include "fixed/fixed.hpp"

namespace {

using fixed::overflow;
using fixed::rounding;
using fixed::signedness;

template <class T>
std::string printed(const T& v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// ---- rounding ---------------------------------------------------------------------------------

struct shift_case {
  std::int64_t value;
  int shift;
  std::int64_t floor, toward_zero, ties_up, ties_even;
};

TEST(FixedRounding, HandCheckedQuotients) {
  const shift_case cases[] = {
      {5, 1, 2, 2, 3, 2},                   // 2.5
      {7, 1, 3, 3, 4, 4},                   // 3.5
      {-5, 1, -3, -2, -2, -2},              // -2.5
      {-7, 1, -4, -3, -3, -4},              // -3.5
      {-1, 4, -1, 0, 0, 0},                 // -0.0625
      {-8, 4, -1, 0, 0, 0},                 // -0.5: ties up -> 0, ties even -> 0
      {-24, 4, -2, -1, -1, -2},             // -1.5
      {-9, 4, -1, 0, -1, -1},               // -0.5625
      {383, 7, 2, 2, 3, 3},                 // 2.9921875
      {-65280, 7, -510, -510, -510, -510},  // (-256)(255) / 128 = -510 exactly
      {-65281, 7, -511, -510, -510, -510},  // -510.0078125
      {100, 0, 100, 100, 100, 100},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(testing::Message() << c.value << " >> " << c.shift);
    EXPECT_EQ(fixed::shift_right<rounding::floor>(c.value, c.shift), c.floor);
    EXPECT_EQ(fixed::shift_right<rounding::toward_zero>(c.value, c.shift), c.toward_zero);
    EXPECT_EQ(fixed::shift_right<rounding::nearest_ties_up>(c.value, c.shift), c.ties_up);
    EXPECT_EQ(fixed::shift_right<rounding::nearest_ties_even>(c.value, c.shift), c.ties_even);
    EXPECT_EQ(fixed::shift_right(c.value, c.shift, rounding::nearest_ties_even), c.ties_even);
  }
}

TEST(FixedRounding, BoundaryValuesOfEachWidth) {
  constexpr auto min64 = std::numeric_limits<std::int64_t>::min();
  constexpr auto max64 = std::numeric_limits<std::int64_t>::max();
  constexpr auto umax64 = std::numeric_limits<std::uint64_t>::max();
  // -2^63 / 2^63 = -1 exactly; (2^63 - 1) / 2^63 is just below 1.
  static_assert(fixed::shift_right<rounding::toward_zero>(min64, 63) == -1);
  static_assert(fixed::shift_right<rounding::floor>(max64, 63) == 0);
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(max64, 63) == 1);
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(max64, 1) == (max64 - 1) / 2 + 1);  // 2^62
  // (2^64 - 1) / 2^63 = 1.99...: floor 1, nearest 2; / 2 = 2^63 - 0.5 ties to 2^63 (even) and up.
  static_assert(fixed::shift_right<rounding::floor>(umax64, 63) == 1);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(umax64, 63) == 2);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(umax64, 1) == std::uint64_t{1} << 63);
  // int8_t: -128 / 2^7 = -1; 127 / 2^7 = 0.99: nearest 1.
  static_assert(fixed::shift_right<rounding::floor>(std::int8_t{-128}, 7) == -1);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(std::int8_t{127}, 7) == 1);
  SUCCEED();
}

TEST(FixedRounding, ShiftsAtOrBeyondTheWidthAreExact) {
  // int16_t -2^15 / 2^16 = -0.5: floor -1, toward zero 0, ties up 0, ties to even 0.
  constexpr std::int16_t min16 = -32768;
  static_assert(fixed::shift_right<rounding::floor>(min16, 16) == -1);
  static_assert(fixed::shift_right<rounding::toward_zero>(min16, 16) == 0);
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(min16, 16) == 0);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(min16, 16) == 0);
  // uint16_t 0x8000 / 2^16 = 0.5: ties up 1, ties to even 0; 0x8001 / 2^16 > 0.5: both 1.
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(std::uint16_t{0x8000}, 16) == 1);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(std::uint16_t{0x8000}, 16) == 0);
  static_assert(fixed::shift_right<rounding::nearest_ties_even>(std::uint16_t{0x8001}, 16) == 1);
  // 0xffff / 2^17 < 0.5: 0; -1 / 2^200: floor -1, else 0.
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(std::uint16_t{0xffff}, 17) == 0);
  static_assert(fixed::shift_right<rounding::floor>(std::int64_t{-1}, 200) == -1);
  static_assert(fixed::shift_right<rounding::nearest_ties_up>(std::int64_t{-1}, 200) == 0);
  // A negative shift is treated as 0.
  EXPECT_EQ(fixed::shift_right<rounding::floor>(-5, -3), -5);
}

TEST(FixedRounding, Names) {
  EXPECT_STREQ(fixed::name(rounding::nearest_ties_even), "nearest_ties_even");
  EXPECT_STREQ(fixed::name(overflow::saturate), "saturate");
  EXPECT_EQ(std::size(fixed::all_roundings), 4U);
}

// ---- overflow ---------------------------------------------------------------------------------

TEST(FixedOverflow, HandCheckedNarrowing) {
  // 200 = 0xc8: as s8 that is 200 - 256 = -56; clamped to s8 it is 127.
  static_assert(fixed::wrap<8, signedness::is_signed>(200) == -56);
  static_assert(fixed::saturate<8, signedness::is_signed>(200) == 127);
  static_assert(fixed::saturate<8, signedness::is_signed>(-200) == -128);
  static_assert(fixed::wrap<8, signedness::is_unsigned>(-1) == 255);
  static_assert(fixed::saturate<8, signedness::is_unsigned>(-1) == 0);
  static_assert(fixed::saturate<8, signedness::is_unsigned>(std::numeric_limits<std::uint64_t>::max()) == 255);
  static_assert(fixed::wrap<9, signedness::is_signed>(std::int16_t{0x1ff}) == -1);
  static_assert(fixed::wrap<1, signedness::is_signed>(1) == -1);  // s1 holds -1 and 0
  static_assert(fixed::wrap<64, signedness::is_unsigned>(std::uint64_t{5}) == 5);
  static_assert(fixed::narrow<8, signedness::is_unsigned>(300, overflow::wrap) == 44);
  static_assert(fixed::narrow<8, signedness::is_unsigned>(300, overflow::saturate) == 255);
  EXPECT_EQ((fixed::checked<9, signedness::is_signed>(255)), 255);
  EXPECT_EQ((fixed::checked<9, signedness::is_signed>(256)), std::nullopt);
  EXPECT_EQ((fixed::checked<9, signedness::is_signed>(-257)), std::nullopt);
  EXPECT_EQ((fixed::checked<9, signedness::is_unsigned>(std::uint64_t{511})), 511U);
}

TEST(FixedOverflow, RangeBounds) {
  using s1 = fixed::bit_range<1, signedness::is_signed>;
  using u63 = fixed::bit_range<63, signedness::is_unsigned>;
  using s63 = fixed::bit_range<63, signedness::is_signed>;
  static_assert(s1::min == -1 && s1::max == 0);
  static_assert(u63::min == 0 && u63::max == std::numeric_limits<std::int64_t>::max());
  static_assert(s63::min == -(std::int64_t{1} << 62) && s63::max == (std::int64_t{1} << 62) - 1);
  static_assert(u63::contains(std::uint64_t{1} << 62) && !u63::contains(std::uint64_t{1} << 63));
  SUCCEED();
}

// ---- width-carrying integers ------------------------------------------------------------------

TEST(FixedInteger, ResultTypesAreTheDatapathWidths) {
  using fixed::s9, fixed::s10, fixed::s11, fixed::s17, fixed::u8;
  static_assert(std::is_same_v<decltype(u8{} - u8{}), s9>);              // [-255, 255]
  static_assert(std::is_same_v<decltype(u8{} + u8{}), fixed::uint<9>>);  // [0, 510]
  static_assert(std::is_same_v<decltype(u8{} * u8{}), fixed::uint<16>>);
  static_assert(std::is_same_v<decltype(s9{} * u8{}), s17>);              // [-65280, 65025]
  static_assert(std::is_same_v<decltype(s9{} - u8{}), s10>);              // [-511, 255]
  static_assert(std::is_same_v<decltype(s10{} + u8{}), s11>);             // [-512, 766]
  static_assert(std::is_same_v<decltype(s9{} * s9{}), fixed::sint<18>>);  // up to +2^16
  // floor and truncation of s17 by 2^7 fit s10; to nearest can reach 2^9 and needs s11.
  static_assert(std::is_same_v<decltype(fixed::shift_right<rounding::floor, 7>(s17{})), s10>);
  static_assert(std::is_same_v<decltype(fixed::shift_right<rounding::toward_zero, 7>(s17{})), s10>);
  static_assert(std::is_same_v<decltype(fixed::shift_right<rounding::nearest_ties_up, 7>(s17{})), s11>);
  static_assert(std::is_same_v<decltype(fixed::shift_right<7>(s17{}, rounding::floor)), s11>);
  static_assert(std::is_same_v<decltype(fixed::shift_right<rounding::floor, 0>(u8{})), u8>);
  // Widening is implicit, narrowing is not.
  static_assert(std::is_convertible_v<s9, s17> && std::is_convertible_v<u8, s9>);
  static_assert(!std::is_convertible_v<s9, u8> && !std::is_convertible_v<u8, fixed::sint<8>>);
  SUCCEED();
}

TEST(FixedInteger, HandCheckedValues) {
  constexpr auto zero = fixed::u8::literal(0);
  constexpr auto full = fixed::u8::literal(255);
  static_assert((zero - full).value() == -255);
  static_assert((fixed::s9::literal(-256) * full).value() == -65280);
  static_assert((fixed::s9::literal(255) * full).value() == 65025);
  // (-256)(255) >> 7 = -510 exactly; 65025 / 128 = 508.0078: floor 508, nearest 508.
  static_assert(fixed::shift_right<rounding::floor, 7>(fixed::s9::literal(-256) * full).value() == -510);
  static_assert(fixed::shift_right<rounding::nearest_ties_up, 7>(fixed::s9::literal(255) * full).value() == 508);
  static_assert(fixed::u8::from_wrapped(300).value() == 44);
  static_assert(fixed::u8::from_saturated(-5).value() == 0);
  static_assert(fixed::u8::from_saturated(std::numeric_limits<std::uint64_t>::max()).value() == 255);
  static_assert(fixed::s9::from_wrapped(std::numeric_limits<std::uint64_t>::max()).value() == -1);
  static_assert(!fixed::u8::from_checked(256).has_value() && fixed::u8::from_checked(255U)->value() == 255);
  static_assert(fixed::s11::literal(-300).narrow<8, signedness::is_unsigned, overflow::wrap>().value() == 212);
  static_assert(fixed::s11::literal(-300).narrow<8, signedness::is_unsigned, overflow::saturate>().value() == 0);
  static_assert(fixed::s11::min_value == -1024 && fixed::s11::max_value == 1023 && fixed::u8::bits == 8);
  static_assert(fixed::u8::literal(3) < fixed::u8::literal(4) && fixed::u8::literal(4) == fixed::u8::literal(4));
  static_assert(static_cast<std::int32_t>(fixed::s9::literal(-7)) == -7);
  SUCCEED();
}

TEST(FixedInteger, HashFollowsEquality) {
  std::unordered_set<fixed::s9> set{fixed::s9::literal(-3), fixed::s9::literal(4), fixed::s9::literal(-3)};
  EXPECT_EQ(set.size(), 2U);
  EXPECT_EQ(set.count(fixed::s9::literal(-3)), 1U);
  EXPECT_EQ(std::hash<fixed::s9>{}(fixed::s9::literal(-3)), std::hash<fixed::s9>{}(fixed::s9::literal(-3)));
}

// ---- fixed_point ------------------------------------------------------------------------------

using colour = fixed::gs_colour;  // u8, 0x80 = 1.0
using q8_8 = fixed::fixed_point<std::int16_t, 8>;

template <rounding R, overflow O, class T = q8_8>
constexpr std::optional<std::int64_t> raw_of(double d) {
  const auto v = T::template from_double<R, O>(d);
  return v ? std::optional<std::int64_t>(v->raw()) : std::nullopt;
}

TEST(FixedPoint, GsColourScale) {
  static_assert(colour::from_raw(0x80).to_double() == 1.0);
  static_assert(colour::from_raw(0xff).to_double() == 1.9921875);  // 255 / 128
  static_assert(colour::from_integer<overflow::saturate>(1).raw() == 0x80);
  static_assert(colour::from_integer<overflow::saturate>(2).raw() == 0xff);  // 2.0 > max 1.99
  static_assert(colour::from_integer<overflow::wrap>(2).raw() == 0x00);      // 256 mod 256
  static_assert(colour::from_integer<overflow::wrap>(3).raw() == 0x80);      // 384 mod 256
  static_assert(colour::from_integer<overflow::saturate>(-1).raw() == 0x00);
  static_assert(colour::from_integer<overflow::saturate>(std::uint64_t{1} << 63).raw() == 0xff);
  static_assert(q8_8::from_integer<overflow::wrap>((std::int64_t{1} << 60) + 3).raw() == 0x300);  // 2^68 vanishes
  static_assert(q8_8::from_integer<overflow::saturate>(-128).raw() == -0x8000);
  static_assert(q8_8::from_integer<overflow::saturate>(-129).raw() == -0x8000);
  static_assert(q8_8::from_integer<overflow::saturate>(128).raw() == 0x7fff);
  static_assert(colour::fraction_bits == 7 && colour::integer_bits == 1 && q8_8::integer_bits == 7);
  SUCCEED();
}

TEST(FixedPoint, FromDouble) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ((raw_of<rounding::floor, overflow::saturate>(nan)), std::nullopt);
  EXPECT_EQ((raw_of<rounding::floor, overflow::wrap>(nan)), std::nullopt);
  EXPECT_EQ((raw_of<rounding::floor, overflow::wrap>(inf)), std::nullopt);
  static_assert(raw_of<rounding::floor, overflow::saturate>(inf) == 0x7fff);
  static_assert(raw_of<rounding::floor, overflow::saturate>(-inf) == -0x8000);
  static_assert(raw_of<rounding::floor, overflow::saturate>(1.5) == 0x180);
  // 2.5/256 and -2.5/256: raw 2.5 and -2.5.
  static_assert(raw_of<rounding::floor, overflow::saturate>(2.5 / 256) == 2);
  static_assert(raw_of<rounding::toward_zero, overflow::saturate>(-2.5 / 256) == -2);
  static_assert(raw_of<rounding::floor, overflow::saturate>(-2.5 / 256) == -3);
  static_assert(raw_of<rounding::nearest_ties_up, overflow::saturate>(2.5 / 256) == 3);
  static_assert(raw_of<rounding::nearest_ties_up, overflow::saturate>(-2.5 / 256) == -2);
  static_assert(raw_of<rounding::nearest_ties_even, overflow::saturate>(2.5 / 256) == 2);
  static_assert(raw_of<rounding::nearest_ties_even, overflow::saturate>(-3.5 / 256) == -4);
  // The largest double below 1/2 rounds to 0 (floor(x + 0.5) would round it to 1).
  static_assert(raw_of<rounding::nearest_ties_up, overflow::saturate>(0.49999999999999994 / 256) == 0);
  // 128.0 is 0x8000: saturates to 0x7fff, wraps to -0x8000; 256 + 1/256 wraps to raw 1.
  static_assert(raw_of<rounding::floor, overflow::saturate>(128.0) == 0x7fff);
  static_assert(raw_of<rounding::floor, overflow::wrap>(128.0) == -0x8000);
  static_assert(raw_of<rounding::floor, overflow::wrap>(256.0 + 1.0 / 256) == 1);
  // 1e300 · 2^8 is a multiple of 2^16 (its last mantissa bit is worth 2^944): wraps to 0.
  static_assert(raw_of<rounding::floor, overflow::wrap>(1e300) == 0);
  // Fuzz finding (fuzz/corpus/fixed_ops/regression-from_double-wrap-overflow): d = -0x1.fffffffffffffp+1008
  // (bits 0xfeffffffffffffff) times 2^31 overflows a double to -inf, yet d is finite and a multiple of
  // 2^956, so d·2^31 mod 2^32 = 0: wrap gives 0, not nullopt.
  using q0_31 = fixed::fixed_point<std::int32_t, 31>;
  EXPECT_EQ((raw_of<rounding::floor, overflow::wrap, q0_31>(-0x1.fffffffffffffp+1008)),
            0);  // run time: the product overflows
  // 2^51 + 1/2 (exact in a double) at F = 0: ties to even 2^51 -> wraps to 0; ties up -> 1.
  using i32 = fixed::fixed_point<std::int32_t, 0>;
  static_assert(raw_of<rounding::nearest_ties_even, overflow::wrap, i32>(0x1p51 + 0.5) == 0);
  static_assert(raw_of<rounding::nearest_ties_up, overflow::wrap, i32>(0x1p51 + 0.5) == 1);
  static_assert(raw_of<rounding::floor, overflow::saturate, colour>(-0.25) == 0);
  SUCCEED();
}

TEST(FixedPoint, ConvertAddSubMul) {
  using i32 = fixed::fixed_point<std::int32_t, 0>;
  // 0xff = 1.9921875: floor 1, nearest 2; as 8.8 it is raw 0x1fe.
  static_assert(colour::from_raw(0xff).convert<rounding::floor, overflow::saturate, std::int32_t, 0>() ==
                i32::from_raw(1));
  static_assert(colour::from_raw(0xff).convert<rounding::nearest_ties_up, overflow::saturate, std::int32_t, 0>() ==
                i32::from_raw(2));
  static_assert(colour::from_raw(0xff).convert<rounding::floor, overflow::saturate, std::int16_t, 8>() ==
                q8_8::from_raw(0x1fe));
  // 0xc0 + 0xc0 = 0x180: saturates to 0xff, wraps to 0x80; 0x10 - 0x20 saturates to 0, wraps to 0xf0.
  static_assert(fixed::add<overflow::saturate>(colour::from_raw(0xc0), colour::from_raw(0xc0)).raw() == 0xff);
  static_assert(fixed::add<overflow::wrap>(colour::from_raw(0xc0), colour::from_raw(0xc0)).raw() == 0x80);
  static_assert(fixed::sub<overflow::saturate>(colour::from_raw(0x10), colour::from_raw(0x20)).raw() == 0x00);
  static_assert(fixed::sub<overflow::wrap>(colour::from_raw(0x10), colour::from_raw(0x20)).raw() == 0xf0);
  // 1.0 · 1.0 = 1.0; 0xff · 0xff = 65025 / 128 = 508.0078: floor 508 -> wraps to 252, saturates to 255.
  static_assert(
      fixed::mul<rounding::floor, overflow::wrap, std::uint8_t, 7>(colour::from_raw(0x80), colour::from_raw(0x80))
          .raw() == 0x80);
  static_assert(
      fixed::mul<rounding::floor, overflow::wrap, std::uint8_t, 7>(colour::from_raw(0xff), colour::from_raw(0xff))
          .raw() == 252);
  static_assert(
      fixed::mul<rounding::floor, overflow::saturate, std::uint8_t, 7>(colour::from_raw(0xff), colour::from_raw(0xff))
          .raw() == 255);
  // (2^32 - 1)^2 = 2^64 - 2^33 + 1 exceeds int64: saturates to 0xffffffff, wraps to 1.
  using u32 = fixed::fixed_point<std::uint32_t, 0>;
  constexpr auto big = u32::from_raw(0xffffffffU);
  static_assert(fixed::mul<rounding::floor, overflow::saturate, std::uint32_t, 0>(big, big).raw() == 0xffffffffU);
  static_assert(fixed::mul<rounding::floor, overflow::wrap, std::uint32_t, 0>(big, big).raw() == 1U);
  static_assert(fixed::mul<rounding::floor, overflow::saturate, std::int32_t, 0>(big, big).raw() == 0x7fffffff);
  // -2^31 · (2^32 - 1) = -2^63 + 2^31 fits int64; saturates to -2^31.
  using s32 = fixed::fixed_point<std::int32_t, 0>;
  static_assert(fixed::mul<rounding::floor, overflow::saturate, std::int32_t, 0>(
                    s32::from_raw(std::numeric_limits<std::int32_t>::min()), big)
                    .raw() == std::numeric_limits<std::int32_t>::min());
  SUCCEED();
}

TEST(FixedPoint, NumericLimits) {
  using L = std::numeric_limits<colour>;
  static_assert(L::is_specialized && !L::is_signed && !L::is_integer && L::is_exact && L::digits == 8);
  static_assert(L::lowest().raw() == 0 && L::max().raw() == 0xff && L::min().raw() == 1 && L::epsilon().raw() == 1);
  using Q = std::numeric_limits<q8_8>;
  static_assert(Q::is_signed && Q::digits == 15 && Q::lowest().raw() == -0x8000 && Q::max().raw() == 0x7fff);
  using I = std::numeric_limits<fixed::fixed_point<std::int16_t, 0>>;
  static_assert(I::is_integer && I::min() == I::lowest());  // as for built-in integers
  SUCCEED();
}

TEST(FixedPoint, HashFollowsEquality) {
  std::unordered_set<colour> set{colour::from_raw(0x80), colour::from_raw(0x80), colour::from_raw(0x81)};
  EXPECT_EQ(set.size(), 2U);
}

// ---- printing ---------------------------------------------------------------------------------

TEST(FixedPrinting, ValueAndRawHex) {
  EXPECT_EQ(printed(colour::from_raw(0x80)), "1 [raw 0x80]");
  EXPECT_EQ(printed(colour::from_raw(0xff)), "1.9921875 [raw 0xff]");
  EXPECT_EQ(printed(q8_8::from_raw(-0x180)), "-1.5 [raw 0xfe80]");
  EXPECT_EQ(printed(fixed::s9::literal(-3)), "-3 [s9 0x1fd]");
  EXPECT_EQ(printed(fixed::u8::literal(255)), "255 [u8 0xff]");
  // 2^17 - 65280 = 65792 = 0x10100.
  EXPECT_EQ(printed(fixed::s17::literal(-65280)), "-65280 [s17 0x10100]");
  EXPECT_EQ(fixed::hex(std::int8_t{-1}), "0xff");
  EXPECT_EQ(fixed::hex(std::uint32_t{1}), "0x00000001");
  EXPECT_EQ(fixed::hex(std::int64_t{-2}), "0xfffffffffffffffe");
  EXPECT_EQ(fixed::hex(std::uint16_t{0xab}, 2), "0xab");
}

}  // namespace
