// tests/fixed/property_test.cpp — algebraic laws of include/fixed, checked by rapidcheck on random
// inputs of every width up to 64 bits (the exhaustive tests cover 8- to 17-bit domains in full).
// Every property logs its inputs in hex (RC_LOG), which rapidcheck prints with a counterexample.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "fixed/fixed.hpp"
#include "reference.hpp"

namespace {

using fixed::overflow;
using fixed::rounding;
using fixed::signedness;
__extension__ typedef __int128 i128;  // exact reference arithmetic for 64-bit inputs

// Mostly arbitrary values, often the boundary values of T.
template <class T>
rc::Gen<T> values() {
  using L = std::numeric_limits<T>;
  return rc::gen::weightedOneOf<T>({{3, rc::gen::arbitrary<T>()},
                                    {1, rc::gen::element<T>(L::min(), L::max(), static_cast<T>(L::min() + 1),
                                                            static_cast<T>(L::max() - 1), 0, 1, static_cast<T>(-1))}});
}

// Shifts from 0 to 8 beyond the width of T.
template <class T>
rc::Gen<int> shifts() {
  return rc::gen::inRange(0, fixed::width_v<T> + 9);
}

template <class T>
bool floor_and_truncation_differ_only_for_negative_non_multiples() {
  return rc::check("floor vs toward_zero", [] {
    const T v = *values<T>();
    const int k = *shifts<T>();
    RC_LOG() << "v = " << fixed::hex(v) << ", k = " << k << "\n";
    const i128 fl = fixed::shift_right<rounding::floor>(v, k);
    const i128 tz = fixed::shift_right<rounding::toward_zero>(v, k);
    const bool negative_non_multiple = v < 0 && i128{v} % fixed_ref::pow2<i128>(k) != 0;
    RC_ASSERT(tz - fl == (negative_non_multiple ? 1 : 0));
  });
}

template <class T>
bool nearest_is_floor_or_one_above_and_ties_decide_the_modes() {
  return rc::check("nearest vs floor", [] {
    const T v = *values<T>();
    const int k = *shifts<T>();
    RC_LOG() << "v = " << fixed::hex(v) << ", k = " << k << "\n";
    const i128 fl = fixed::shift_right<rounding::floor>(v, k);
    const i128 up = fixed::shift_right<rounding::nearest_ties_up>(v, k);
    const i128 even = fixed::shift_right<rounding::nearest_ties_even>(v, k);
    RC_ASSERT(up - fl == 0 || up - fl == 1);
    RC_ASSERT(even - fl == 0 || even - fl == 1);
    // The modes differ exactly on ties, v = (fl + 1/2)·2^k, where ties_even picks the even one.
    const bool tie = k > 0 && 2 * (i128{v} - fl * fixed_ref::pow2<i128>(k)) == fixed_ref::pow2<i128>(k);
    RC_ASSERT((up != even) == (tie && fl % 2 == 0));
    RC_ASSERT(!tie || even % 2 == 0);
  });
}

template <class T>
bool every_mode_matches_the_wide_reference() {
  return rc::check("shift_right vs __int128 reference", [] {
    const T v = *values<T>();
    const int k = *shifts<T>();
    RC_LOG() << "v = " << fixed::hex(v) << ", k = " << k << "\n";
    for (const rounding r : fixed::all_roundings) {
      RC_ASSERT((i128{fixed::shift_right(v, k, r)} == fixed_ref::divide_pow2<i128>(v, k, r)));
    }
  });
}

template <class T>
void check_rounding_laws() {
  EXPECT_TRUE(floor_and_truncation_differ_only_for_negative_non_multiples<T>());
  EXPECT_TRUE(nearest_is_floor_or_one_above_and_ties_decide_the_modes<T>());
  EXPECT_TRUE(every_mode_matches_the_wide_reference<T>());
}

TEST(FixedProperty, RoundingLaws) {
  check_rounding_laws<std::int8_t>();
  check_rounding_laws<std::uint8_t>();
  check_rounding_laws<std::int32_t>();
  check_rounding_laws<std::uint32_t>();
  check_rounding_laws<std::int64_t>();
  check_rounding_laws<std::uint64_t>();
}

template <int N, signedness S, class T>
bool saturate_is_monotone_and_idempotent() {
  return rc::check("saturate", [] {
    const T a = *values<T>();
    const T b = *values<T>();
    RC_LOG() << "a = " << fixed::hex(a) << ", b = " << fixed::hex(b) << ", N = " << N << "\n";
    const T sa = fixed::saturate<N, S>(a);
    const T sb = fixed::saturate<N, S>(b);
    RC_ASSERT((a <= b) <= (sa <= sb));  // a <= b implies sa <= sb
    RC_ASSERT((fixed::saturate<N, S>(sa) == sa));
    RC_ASSERT((fixed::checked<N, S>(a).has_value() == (sa == a)));
    RC_ASSERT((fixed::bit_range<N, S>::contains(sa)));
  });
}

template <int N, signedness S>
bool wrap_is_a_ring_homomorphism() {
  static_assert(N <= 31, "a + b, a · b and the sums/products of N-bit residues must be exact in int64");
  return rc::check("wrap", [] {
    const std::int64_t a = *values<std::int32_t>();
    const std::int64_t b = *values<std::int32_t>();
    RC_LOG() << "a = " << fixed::hex(a) << ", b = " << fixed::hex(b) << ", N = " << N << "\n";
    const auto w = [](std::int64_t x) { return fixed::wrap<N, S>(x); };
    RC_ASSERT(w(a + b) == w(w(a) + w(b)));
    RC_ASSERT(w(a * b) == w(w(a) * w(b)));
    RC_ASSERT(w(-a) == w(-w(a)));
    RC_ASSERT(w(w(a)) == w(a));
    RC_ASSERT((fixed::bit_range<N, S>::contains(w(a))));
  });
}

template <int N>
void check_overflow_laws() {
  EXPECT_TRUE((saturate_is_monotone_and_idempotent<N, signedness::is_signed, std::int64_t>()));
  EXPECT_TRUE((saturate_is_monotone_and_idempotent<N, signedness::is_unsigned, std::int64_t>()));
  EXPECT_TRUE((saturate_is_monotone_and_idempotent<N, signedness::is_unsigned, std::uint64_t>()));
  if constexpr (N <= 31) {
    EXPECT_TRUE((wrap_is_a_ring_homomorphism<N, signedness::is_signed>()));
    EXPECT_TRUE((wrap_is_a_ring_homomorphism<N, signedness::is_unsigned>()));
  }
}

TEST(FixedProperty, OverflowLaws) {
  check_overflow_laws<1>();
  check_overflow_laws<8>();
  check_overflow_laws<9>();
  check_overflow_laws<17>();
  check_overflow_laws<31>();
  check_overflow_laws<63>();
}

TEST(FixedProperty, NarrowAfterWidenIsIdentity) {
  EXPECT_TRUE(rc::check("integer", [] {
    const auto x = fixed::s9::from_wrapped(*values<std::int16_t>());
    const auto c = fixed::u8::from_wrapped(*values<std::uint8_t>());
    RC_LOG() << "x = " << x << ", c = " << c << "\n";
    const fixed::s17 wide = x;
    const fixed::s9 widened_c = c;
    RC_ASSERT((wide.narrow<9, signedness::is_signed, overflow::wrap>()) == x);
    RC_ASSERT((wide.narrow<9, signedness::is_signed, overflow::saturate>()) == x);
    RC_ASSERT((widened_c.narrow<8, signedness::is_unsigned, overflow::saturate>()) == c);
  }));
  EXPECT_TRUE(rc::check("fixed_point", [] {
    const auto x = fixed::gs_colour::from_raw(*values<std::uint8_t>());
    RC_LOG() << "x = " << x << "\n";
    const auto wide = x.convert<rounding::floor, overflow::wrap, std::int32_t, 20>();
    RC_ASSERT((wide.convert<rounding::nearest_ties_even, overflow::saturate, std::uint8_t, 7>()) == x);
    RC_ASSERT((wide.convert<rounding::toward_zero, overflow::wrap, std::uint8_t, 7>()) == x);
  }));
}

TEST(FixedProperty, FromDoubleRoundsAsNamed) {
  using q = fixed::fixed_point<std::int32_t, 12>;
  EXPECT_TRUE(rc::check("to_double then from_double is the identity", [] {
    const auto x = q::from_raw(*values<std::int32_t>());
    RC_LOG() << "x = " << x << "\n";
    RC_ASSERT((q::from_double<rounding::floor, overflow::wrap>(x.to_double())) == x);
    RC_ASSERT((q::from_double<rounding::nearest_ties_even, overflow::saturate>(x.to_double())) == x);
  }));
  EXPECT_TRUE(rc::check("from_double satisfies the defining inequalities", [] {
    // d in (-2^19, 2^19): d·2^12 is exact and in range. For floor, raw <= s < raw + 1. For nearest,
    // |s - raw| <= 1/2, and s - raw is exact (Sterbenz: s is within 1/2 of the integer raw).
    const double d = *rc::gen::map(rc::gen::arbitrary<std::int64_t>(), [](std::int64_t i) {
      return static_cast<double>(i % (std::int64_t{1} << 50)) / static_cast<double>(std::int64_t{1} << 31);
    });
    RC_LOG() << "d = " << std::hexfloat << d << "\n";
    const double s = d * 4096;
    const auto fl = q::from_double<rounding::floor, overflow::saturate>(d);
    const auto up = q::from_double<rounding::nearest_ties_up, overflow::saturate>(d);
    const auto even = q::from_double<rounding::nearest_ties_even, overflow::saturate>(d);
    RC_ASSERT(fl && up && even);
    RC_ASSERT(fl->raw() <= s && s < fl->raw() + 1.0);
    RC_ASSERT(2 * (s - up->raw()) >= -1.0 && 2 * (s - up->raw()) < 1.0);
    RC_ASSERT(2 * (s - even->raw()) >= -1.0 && 2 * (s - even->raw()) <= 1.0);
    RC_ASSERT(std::abs(2 * (s - even->raw())) != 1.0 || even->raw() % 2 == 0);
  }));
}

TEST(FixedProperty, ProductMatchesWideReference) {
  // 32-bit formats, every overflow: the product rounded by the reference, then wrapped/saturated.
  using u = fixed::fixed_point<std::uint32_t, 8>;
  using s = fixed::fixed_point<std::int32_t, 8>;
  EXPECT_TRUE(rc::check("mul", [] {
    const auto a = u::from_raw(*values<std::uint32_t>());
    const auto b = u::from_raw(*values<std::uint32_t>());
    const auto c = s::from_raw(*values<std::int32_t>());
    RC_LOG() << "a = " << a << ", b = " << b << ", c = " << c << "\n";
    fixed_ref::for_each_rounding([&]<rounding R>() {
      const i128 ab = fixed_ref::divide_pow2<i128>(i128{a.raw()} * b.raw(), 8, R);
      const i128 ac = fixed_ref::divide_pow2<i128>(i128{a.raw()} * c.raw(), 8, R);
      RC_ASSERT(
          (i128{fixed::mul<R, overflow::wrap, std::uint32_t, 8>(a, b).raw()} == fixed_ref::wrap<i128>(ab, 32, false)));
      RC_ASSERT((i128{fixed::mul<R, overflow::saturate, std::int32_t, 8>(a, b).raw()} ==
                 fixed_ref::saturate<i128>(ab, 32, true)));
      RC_ASSERT(
          (i128{fixed::mul<R, overflow::wrap, std::int32_t, 8>(a, c).raw()} == fixed_ref::wrap<i128>(ac, 32, true)));
      RC_ASSERT((i128{fixed::mul<R, overflow::saturate, std::uint32_t, 8>(a, c).raw()} ==
                 fixed_ref::saturate<i128>(ac, 32, false)));
    });
  }));
}

}  // namespace
