// fuzz/wide_reference.hpp — the slow reference for fixed_ops: exact arithmetic on 128-bit integers,
// written with division and remainder (the library under test uses masks and shifts), so that the
// two agree only if both are right. Every operand of the harness is at most 64 bits wide and every
// shift at most 120, so no operation here can overflow 128 bits.
#pragma once

#include <cstdint>
#include <string>

#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"

namespace gsdot3::fuzz {

__extension__ typedef __int128 i128;  // __extension__: GNU types, accepted under -Wpedantic
__extension__ typedef unsigned __int128 u128;

constexpr i128 pow2(int k) { return i128{1} << k; }

// floor(n / d) for d > 0.
constexpr i128 floor_div(i128 n, i128 d) {
  const i128 q = n / d;  // C++ division truncates toward zero
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// n / 2^k rounded as r, for any k (k <= 0 is no division).
constexpr i128 exact_shift(i128 n, int k, fixed::rounding r) {
  if (k <= 0) return n;
  if (k > 120) {  // |n| < 2^65, so |n / 2^k| < 2^-55: only floor of a negative leaves zero
    return (r == fixed::rounding::floor && n < 0) ? -1 : 0;
  }
  const i128 d = pow2(k);
  const i128 f = floor_div(n, d);
  switch (r) {
    case fixed::rounding::floor: return f;
    case fixed::rounding::toward_zero: return n / d;
    case fixed::rounding::nearest_ties_up: return floor_div(2 * n + d, 2 * d);  // floor(n/d + 1/2)
    case fixed::rounding::nearest_ties_even: {
      const i128 twice_rem = 2 * (n - f * d);  // in [0, 2d)
      return (twice_rem > d || (twice_rem == d && f % 2 != 0)) ? f + 1 : f;
    }
  }
  return f;
}

constexpr i128 range_min(int n, bool is_signed) { return is_signed ? -pow2(n - 1) : 0; }
constexpr i128 range_max(int n, bool is_signed) { return is_signed ? pow2(n - 1) - 1 : pow2(n) - 1; }

// v mod 2^n, as the representative in the n-bit signed or unsigned range.
constexpr i128 wrap_ref(i128 v, int n, bool is_signed) {
  const i128 m = pow2(n);
  i128 r = ((v % m) + m) % m;
  if (is_signed && r > range_max(n, true)) r -= m;
  return r;
}

constexpr i128 saturate_ref(i128 v, int n, bool is_signed) {
  if (v < range_min(n, is_signed)) return range_min(n, is_signed);
  if (v > range_max(n, is_signed)) return range_max(n, is_signed);
  return v;
}

constexpr i128 narrow_ref(i128 v, int n, bool is_signed, fixed::overflow o) {
  return o == fixed::overflow::wrap ? wrap_ref(v, n, is_signed) : saturate_ref(v, n, is_signed);
}

// "-0x1f" style hex of a 128-bit value (sign and magnitude, so widths never matter).
inline std::string hex128(i128 v) {
  const bool negative = v < 0;
  u128 m = negative ? static_cast<u128>(-(v + 1)) + 1 : static_cast<u128>(v);
  std::string digits;
  do {
    digits.insert(digits.begin(), "0123456789abcdef"[static_cast<int>(m % 16)]);
    m /= 16;
  } while (m != 0);
  return (negative ? "-0x" : "0x") + digits;
}

}  // namespace gsdot3::fuzz
