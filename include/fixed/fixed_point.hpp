// fixed/fixed_point.hpp — a fixed-point number: a raw integer of type Rep scaled by 2^-F.
//
// Conversions are explicit, rounding and overflow are named at the call site, raw access is
// raw() / from_raw(). No operation has undefined behaviour: products are formed in 64 bits and
// narrowed with a named overflow policy.
#pragma once

#include <cmath>
#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>

#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"

namespace fixed {

template <std::integral Rep, int F>
class fixed_point {
  static_assert(F >= 0 && F < width_v<Rep>, "fraction bits must fit the representation");
  static_assert(width_v<Rep> <= 32, "representations up to 32 bits (products are formed in 64)");

 public:
  using rep = Rep;
  static constexpr int fraction_bits = F;
  static constexpr int integer_bits = width_v<Rep> - F - (std::is_signed_v<Rep> ? 1 : 0);
  static constexpr signedness sign = std::is_signed_v<Rep> ? signedness::is_signed : signedness::is_unsigned;

  constexpr fixed_point() noexcept = default;

  static constexpr fixed_point from_raw(Rep r) noexcept { return fixed_point(r); }
  constexpr Rep raw() const noexcept { return raw_; }

  // From an integer: value · 2^F, with the named overflow behaviour.
  template <overflow O, std::integral I>
  static constexpr fixed_point from_integer(I v) noexcept {
    const std::int64_t scaled = static_cast<std::int64_t>(static_cast<std::uint64_t>(static_cast<std::int64_t>(v)) << F);
    return fixed_point(static_cast<Rep>(narrow<width_v<Rep>, sign, O>(clamp64<I>(v, scaled))));
  }
  // From a double: rounded as R, overflow as O; NaN gives nullopt.
  template <rounding R, overflow O>
  static std::optional<fixed_point> from_double(double d) noexcept {
    if (std::isnan(d)) return std::nullopt;
    const double scaled = std::ldexp(d, F);
    double r = 0;
    switch (R) {
      case rounding::floor: r = std::floor(scaled); break;
      case rounding::toward_zero: r = std::trunc(scaled); break;
      case rounding::nearest_ties_up: r = std::floor(scaled + 0.5); break;
      case rounding::nearest_ties_even: r = std::nearbyint(scaled); break;  // default FE_TONEAREST
    }
    constexpr double lo = static_cast<double>(std::numeric_limits<Rep>::min());
    constexpr double hi = static_cast<double>(std::numeric_limits<Rep>::max());
    if (O == overflow::saturate) {
      if (r < lo) return from_raw(std::numeric_limits<Rep>::min());
      if (r > hi) return from_raw(std::numeric_limits<Rep>::max());
      return from_raw(static_cast<Rep>(r));
    }
    // wrap: reduce modulo 2^width in exact double arithmetic (values up to 2^53 are exact).
    if (std::fabs(r) >= 9007199254740992.0) return std::nullopt;
    return from_raw(static_cast<Rep>(wrap<width_v<Rep>, sign>(static_cast<std::int64_t>(r))));
  }

  explicit constexpr operator double() const noexcept { return static_cast<double>(raw_) / static_cast<double>(std::int64_t{1} << F); }
  constexpr double to_double() const noexcept { return static_cast<double>(*this); }

  // To another fraction width: shifting right rounds as R, shifting left or widening never loses.
  template <rounding R, overflow O, std::integral Rep2, int F2>
  constexpr fixed_point<Rep2, F2> convert() const noexcept {
    std::int64_t r = raw_;
    if constexpr (F2 < F) {
      r = shift_right<R>(r, F - F2);
    } else if constexpr (F2 > F) {
      r = static_cast<std::int64_t>(static_cast<std::uint64_t>(r) << (F2 - F));
    }
    return fixed_point<Rep2, F2>::from_raw(
        static_cast<Rep2>(narrow<width_v<Rep2>, fixed_point<Rep2, F2>::sign, O>(r)));
  }

  friend constexpr bool operator==(fixed_point, fixed_point) noexcept = default;
  friend constexpr auto operator<=>(fixed_point, fixed_point) noexcept = default;

 private:
  explicit constexpr fixed_point(Rep r) noexcept : raw_(r) {}
  // A value whose scaled form cannot be represented in 64 bits saturates before narrowing.
  template <std::integral I>
  static constexpr std::int64_t clamp64(I v, std::int64_t scaled) noexcept {
    constexpr std::int64_t lim = std::int64_t{1} << (62 - F);
    if (static_cast<std::int64_t>(v) >= lim) return std::numeric_limits<std::int64_t>::max() >> 1;
    if (static_cast<std::int64_t>(v) <= -lim) return std::numeric_limits<std::int64_t>::min() >> 1;
    return scaled;
  }
  Rep raw_ = 0;
};

// a + b and a - b at the same format, overflow named.
template <overflow O, std::integral Rep, int F>
constexpr fixed_point<Rep, F> add(fixed_point<Rep, F> a, fixed_point<Rep, F> b) noexcept {
  const std::int64_t s = static_cast<std::int64_t>(a.raw()) + b.raw();
  return fixed_point<Rep, F>::from_raw(static_cast<Rep>(narrow<width_v<Rep>, fixed_point<Rep, F>::sign, O>(s)));
}
template <overflow O, std::integral Rep, int F>
constexpr fixed_point<Rep, F> sub(fixed_point<Rep, F> a, fixed_point<Rep, F> b) noexcept {
  const std::int64_t s = static_cast<std::int64_t>(a.raw()) - b.raw();
  return fixed_point<Rep, F>::from_raw(static_cast<Rep>(narrow<width_v<Rep>, fixed_point<Rep, F>::sign, O>(s)));
}
// a * b into format (RepOut, FOut): exact 64-bit product, then rounding R and overflow O.
template <rounding R, overflow O, std::integral RepOut, int FOut, std::integral RA, int FA, std::integral RB, int FB>
constexpr fixed_point<RepOut, FOut> mul(fixed_point<RA, FA> a, fixed_point<RB, FB> b) noexcept {
  std::int64_t p = static_cast<std::int64_t>(a.raw()) * b.raw();  // |p| < 2^62
  constexpr int shift = FA + FB - FOut;
  static_assert(shift >= 0 && shift < 63, "the output format may not have more fraction bits than the product");
  p = shift_right<R>(p, shift);
  return fixed_point<RepOut, FOut>::from_raw(
      static_cast<RepOut>(narrow<width_v<RepOut>, fixed_point<RepOut, FOut>::sign, O>(p)));
}

// The GS's colour and alpha channels: 8-bit unsigned with 0x80 = 1.0 (so 0xFF = 1.9921875).
using gs_colour = fixed_point<std::uint8_t, 7>;
// Gouraud colour as the rasteriser steps it: 8 integer bits and 7 fraction bits (8.7).
using gs_gouraud = fixed_point<std::int32_t, 7>;

}  // namespace fixed

template <std::integral Rep, int F>
class std::numeric_limits<fixed::fixed_point<Rep, F>> {
  using T = fixed::fixed_point<Rep, F>;
  using L = std::numeric_limits<Rep>;

 public:
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = L::is_signed;
  static constexpr bool is_integer = F == 0;
  static constexpr bool is_exact = true;
  static constexpr bool has_infinity = false;
  static constexpr bool has_quiet_NaN = false;
  static constexpr bool has_signaling_NaN = false;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr int radix = 2;
  static constexpr int digits = L::digits;
  static constexpr int digits10 = L::digits10;
  static constexpr T min() noexcept { return T::from_raw(Rep{1}); }  // smallest positive, like float
  static constexpr T lowest() noexcept { return T::from_raw(L::min()); }
  static constexpr T max() noexcept { return T::from_raw(L::max()); }
  static constexpr T epsilon() noexcept { return T::from_raw(Rep{1}); }
  static constexpr T round_error() noexcept { return T::from_raw(Rep{1}); }
  static constexpr T denorm_min() noexcept { return T::from_raw(Rep{1}); }
};
