// tests/schemes/powervr/bounds.hpp — an a-priori bound on the bump unit's 8-bit error against the
// exact identity value 255·clamp((1 − S_l) + S_l·N·L, 0, 1), derived from the rounding steps (not
// from measurements): output rounding 1/2; K1, K2, K3 each within 1/2 of 255·k, weighted by 1,
// |sin S| and |cos S·cos(R − Q)|, so ≤ 1/2 + √2/2; fixedB tables: K2's sine within 2^−(B+1), K3's
// cos S·cos(R − Q) within 2^−(B+1)·2 (two table entries) + 2^−(B+1) (product rounding) + 2^−2B, at
// most 255 each, so ≤ 255·(4·2^−(B+1) + 2^−2B); float: 255 times a few float ulps (1e-3 covers it).
#pragma once

#include <cmath>

#include "powervr/evaluate.hpp"

namespace gsdot3::schemes::powervr::test {

inline double identity_error_bound(precision p) {
  const double base = 0.5 + 0.5 + std::sqrt(2.0) / 2.0;
  if (p == precision::float32) return base + 1e-3;
  const double step = std::ldexp(1.0, -table_bits(p));
  return base + 255.0 * (2.0 * step + step * step);
}

}  // namespace gsdot3::schemes::powervr::test
