// proofs_triangle_thirds.hpp — what proofs_triangle_lattice and proofs_triangle_free_x share: the
// packed lights of L_S by two of their channels, and a folded level as the multiply sees it.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "proofs/domains.hpp"

namespace gsdot3::bench {

// The packed values of channel c of L_S for given values a, b of channels (c + 1) % 3 and
// (c + 2) % 3 (folded: any sign), tabulated.
class packed_thirds {
 public:
  packed_thirds(int s, std::size_t c) : s_(s), side_(2 * s + 1), values_(static_cast<std::size_t>(side_ * side_)) {
    for (int a = -s; a <= s; ++a)
      for (int b = -s; b <= s; ++b)
        for (int v = -s; v <= s; ++v) {
          proofs::ivec3 l{};
          l[(c + 1) % 3] = a, l[(c + 2) % 3] = b, l[c] = v;
          if (proofs::is_packed_light(s, l)) values_[index(a, b)].push_back(v);
        }
  }
  const std::vector<int>& operator()(int a, int b) const {
    static const std::vector<int> none;
    if (a < -s_ || b < -s_ || a > s_ || b > s_) return none;
    return values_[index(a, b)];
  }

 private:
  std::size_t index(int a, int b) const { return static_cast<std::size_t>((a + s_) * side_ + (b + s_)); }
  int s_, side_;
  std::vector<std::vector<int>> values_;
};

// A channel's folded level at the pixel as the multiply sees it: the level itself, or under
// truncate_to_8 its ceiling where σ_c = −1 and its floor where σ_c = +1 (floor(L_c/128) unfolded; a
// level within 1e-6 of an integer is taken at the integer: the exact case, a hair off the limit,
// decides).
inline double seen_level(double level, bool truncate, int sigma) {
  if (!truncate) return level;
  const double r = std::round(level);
  if (std::fabs(level - r) < 1e-6) return r;
  return sigma < 0 ? std::ceil(level) : std::floor(level);
}

}  // namespace gsdot3::bench
