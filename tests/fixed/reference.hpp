// tests/fixed/reference.hpp — independent references for include/fixed.
//
// Written another way on purpose: no shift or mask is applied to the value. Quotients use C++'s
// truncating / and % on a wider type W (int64 or __int128), rounding is decided by comparing 2·|rem|
// with 2^k, and wrapping is remainder arithmetic. W must hold 2·2^k and the operands exactly.
#pragma once

#include <algorithm>

#include "fixed/rounding.hpp"

namespace fixed_ref {

// 2^k by repeated doubling.
template <class W>
constexpr W pow2(int k) {
  W p = 1;
  for (int i = 0; i < k; ++i) p *= 2;
  return p;
}

// v / 2^k rounded as r. With q = trunc(v / 2^k) and rem = v % 2^k (sign of v), v / 2^k = q + rem/2^k.
template <class W>
constexpr W divide_pow2(W v, int k, fixed::rounding r) {
  const W d = pow2<W>(k);
  const W q = v / d;
  const W rem = v % d;
  if (rem == 0) return q;
  const W other = rem > 0 ? q + 1 : q - 1;  // the neighbour of v / 2^k on the far side from 0
  const W twice_rem = 2 * (rem > 0 ? rem : -rem);
  switch (r) {
    case fixed::rounding::floor: return rem > 0 ? q : other;
    case fixed::rounding::toward_zero: return q;
    case fixed::rounding::nearest_ties_up:
      if (twice_rem != d) return twice_rem < d ? q : other;
      return rem > 0 ? other : q;  // the larger neighbour
    case fixed::rounding::nearest_ties_even:
      if (twice_rem != d) return twice_rem < d ? q : other;
      return q % 2 == 0 ? q : other;
  }
  return q;
}

template <class W>
constexpr W lowest(int n, bool is_signed) {
  return is_signed ? -pow2<W>(n - 1) : 0;
}
template <class W>
constexpr W highest(int n, bool is_signed) {
  return (is_signed ? pow2<W>(n - 1) : pow2<W>(n)) - 1;
}
template <class W>
constexpr bool fits(W v, int n, bool is_signed) {
  return lowest<W>(n, is_signed) <= v && v <= highest<W>(n, is_signed);
}

// The representative of v mod 2^n in the n-bit range.
template <class W>
constexpr W wrap(W v, int n, bool is_signed) {
  const W m = pow2<W>(n);
  W r = v % m;
  if (r < 0) r += m;
  return is_signed && r > highest<W>(n, true) ? r - m : r;
}

template <class W>
constexpr W saturate(W v, int n, bool is_signed) {
  return std::clamp(v, lowest<W>(n, is_signed), highest<W>(n, is_signed));
}

// Test helper: calls f.template operator()<R>() for each of the four rounding modes.
template <class F>
void for_each_rounding(F f) {
  f.template operator()<fixed::rounding::floor>();
  f.template operator()<fixed::rounding::toward_zero>();
  f.template operator()<fixed::rounding::nearest_ties_up>();
  f.template operator()<fixed::rounding::nearest_ties_even>();
}

}  // namespace fixed_ref
