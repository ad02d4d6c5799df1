// fixed/fixed_point.hpp — a fixed-point number: a raw integer of type Rep scaled by 2^-F.
//
// Conversions are explicit, rounding and overflow are named at the call site, raw access is
// raw() / from_raw(). Every operation is constexpr and has no undefined behaviour: sums and products
// are formed exactly in 64 bits and narrowed with a named overflow policy.
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"

namespace fixed {

namespace detail {
// A double rounded to an integer as r, exactly and in constant expressions. Doubles of magnitude
// >= 2^52 (and ±infinity) are already integers; below that, int64 truncation, t - 1, f + 1 and the
// midpoint f + 1/2 are all exact.
constexpr double round_to_integer(double x, rounding r) noexcept {
  if (!(x > -0x1p52 && x < 0x1p52)) return x;
  const double t = static_cast<double>(static_cast<std::int64_t>(x));  // toward zero
  const double f = t > x ? t - 1 : t;                                  // floor
  const double mid = f + 0.5;
  const bool odd = (static_cast<std::int64_t>(f) & 1) != 0;
  switch (r) {
    case rounding::floor: return f;
    case rounding::toward_zero: return t;
    case rounding::nearest_ties_up: return x >= mid ? f + 1 : f;
    case rounding::nearest_ties_even: return x > mid || (x == mid && odd) ? f + 1 : f;
  }
  return f;
}
}  // namespace detail

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

  // From an integer: value · 2^F, with the named overflow behaviour (exact for every value of I).
  template <overflow O, std::integral I>
  static constexpr fixed_point from_integer(I v) noexcept {
    if constexpr (O == overflow::saturate) {
      constexpr auto lo = static_cast<Rep>(std::numeric_limits<Rep>::min() >> F);  // exact: 0 or -2^(w-1-F)
      constexpr auto hi = static_cast<Rep>(std::numeric_limits<Rep>::max() >> F);
      if (std::cmp_less(v, lo)) return from_raw(std::numeric_limits<Rep>::min());
      if (std::cmp_greater(v, hi)) return from_raw(std::numeric_limits<Rep>::max());
      return from_raw(static_cast<Rep>(static_cast<std::int64_t>(v) * (std::int64_t{1} << F)));
    } else {
      // Modular 64-bit arithmetic keeps the low bits of v · 2^F exactly, and wrap needs only those.
      const auto bits = static_cast<std::int64_t>(static_cast<std::uint64_t>(v) << F);
      return from_raw(static_cast<Rep>(wrap<width_v<Rep>, sign>(bits)));
    }
  }
  // From a double: d · 2^F rounded as R (exactly, independent of the FP environment), overflow as O.
  // NaN gives nullopt, and so does ±infinity under wrap (it has no residue mod 2^width).
  template <rounding R, overflow O>
  static constexpr std::optional<fixed_point> from_double(double d) noexcept {
    if (d != d) return std::nullopt;
    const double r = detail::round_to_integer(d * static_cast<double>(std::int64_t{1} << F), R);  // d·2^F is exact
    if constexpr (O == overflow::saturate) {
      if (r <= static_cast<double>(std::numeric_limits<Rep>::min())) return from_raw(std::numeric_limits<Rep>::min());
      if (r >= static_cast<double>(std::numeric_limits<Rep>::max())) return from_raw(std::numeric_limits<Rep>::max());
      return from_raw(static_cast<Rep>(r));
    } else {
      if (r - r != 0) {
        // ±infinity has no residue. A finite d whose d·2^F overflowed (|d| >= 2^(1024-F)) has an ulp of at
        // least 2^(972-F) > 2^w, so d·2^F is a multiple of 2^w: its residue is 0.
        if (d - d != 0) return std::nullopt;
        return from_raw(Rep{0});
      }
      // r - trunc(r / 2^w) · 2^w is an integer in (-2^w, 2^w), so the subtraction is exact.
      constexpr double modulus = static_cast<double>(std::int64_t{1} << width_v<Rep>);
      const double low = r - detail::round_to_integer(r / modulus, rounding::toward_zero) * modulus;
      return from_raw(static_cast<Rep>(wrap<width_v<Rep>, sign>(static_cast<std::int64_t>(low))));
    }
  }

  explicit constexpr operator double() const noexcept {
    return static_cast<double>(raw_) / static_cast<double>(std::int64_t{1} << F);
  }
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
    return fixed_point<Rep2, F2>::from_raw(static_cast<Rep2>(narrow<width_v<Rep2>, fixed_point<Rep2, F2>::sign, O>(r)));
  }

  friend constexpr bool operator==(fixed_point, fixed_point) noexcept = default;
  friend constexpr auto operator<=>(fixed_point, fixed_point) noexcept = default;

 private:
  explicit constexpr fixed_point(Rep r) noexcept : raw_(r) {}
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
// a * b into format (RepOut, FOut): exact product, then rounding R and overflow O. The product fits
// int64 (|a·b| <= 2^31 · (2^32 - 1)) unless both factors are unsigned; then it is formed in uint64.
template <rounding R, overflow O, std::integral RepOut, int FOut, std::integral RA, int FA, std::integral RB, int FB>
constexpr fixed_point<RepOut, FOut> mul(fixed_point<RA, FA> a, fixed_point<RB, FB> b) noexcept {
  constexpr int shift = FA + FB - FOut;
  static_assert(shift >= 0, "the output format may not have more fraction bits than the product");
  using P = std::conditional_t<std::is_unsigned_v<RA> && std::is_unsigned_v<RB>, std::uint64_t, std::int64_t>;
  const P p = shift_right<R>(static_cast<P>(static_cast<P>(a.raw()) * static_cast<P>(b.raw())), shift);
  std::int64_t q = 0;
  if constexpr (std::is_unsigned_v<P>) {
    // Above 2^62, keep the low 32 bits (all wrap needs) and stay above every 32-bit maximum
    // (all saturate needs).
    constexpr std::uint64_t big = std::uint64_t{1} << 62;
    q = static_cast<std::int64_t>(p > big ? (p & 0xFFFF'FFFFU) | big : p);
  } else {
    q = p;
  }
  return fixed_point<RepOut, FOut>::from_raw(
      static_cast<RepOut>(narrow<width_v<RepOut>, fixed_point<RepOut, FOut>::sign, O>(q)));
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
  // Smallest positive value, as for floating point; for F = 0 the lowest value, as for integers.
  static constexpr T min() noexcept { return F == 0 ? lowest() : T::from_raw(Rep{1}); }
  static constexpr T lowest() noexcept { return T::from_raw(L::min()); }
  static constexpr T max() noexcept { return T::from_raw(L::max()); }
  static constexpr T epsilon() noexcept { return T::from_raw(Rep{1}); }
  static constexpr T round_error() noexcept { return T::from_raw(Rep{1}); }
  static constexpr T denorm_min() noexcept { return T::from_raw(Rep{1}); }
};

// Hashes the raw bits, so equal values of one format hash equally.
template <std::integral Rep, int F>
struct std::hash<fixed::fixed_point<Rep, F>> {
  std::size_t operator()(fixed::fixed_point<Rep, F> v) const noexcept { return std::hash<Rep>{}(v.raw()); }
};
