// normal_encoding/cell_pieces.hpp — internal to the rounding-cell worst case (cells.hpp): the running
// worst cell, which codes a run enumerates, and the two ways of cutting a code's cell into pieces:
// sphere ∩ half-spaces for the planar methods (planar_cells.cpp), branch and bound on the images of a
// square's edges for the Lambert family (lambert_cells.cpp). cells.cpp splits the codes between threads.
#pragma once

#include <algorithm>
#include <cstdint>

#include "normal_encoding/cells.hpp"

namespace gsdot3::normal_encoding::cell_pieces {

// The running worst cell. Ties (equal angles, e.g. mirror-image cells) go to the least code in
// lexicographic order, and the first NaN cell is the least such code, so the result does not depend on
// how the codes are split between threads.
inline bool before(const code& a, const code& b) noexcept {
  return std::lexicographical_compare(a.c, a.c + 3, b.c, b.c + 3);
}
struct acc {
  worst_case w;
  double sup_rad = -1, upper_rad = -1;
  vec3 d{};  // the decoded direction of the worst cell
  void add_nonfinite(code q, vec3 p) {
    if (w.nonfinite_cells++ == 0 || before(q, w.nonfinite_q)) {
      w.nonfinite_q = q;
      w.nonfinite_n = p;
    }
  }
  void add(code q, vec3 dn, double a, vec3 p, double upper) {
    if (a > sup_rad || (a == sup_rad && before(q, w.q))) {
      sup_rad = a;
      w.q = q;
      w.n = p;
      d = dn;
    }
    upper_rad = std::max(upper_rad, upper);
  }
  void merge(const acc& later);
};

// Which codes (i, j) a run enumerates: those in the window, and with the dihedral reduction
// (cells.cpp) only i >= j >= first_positive.
struct code_filter {
  bool reduce = false;
  code_window window{};
  std::uint32_t first_positive = 0;
  bool skipped(std::uint32_t i, std::uint32_t j) const {
    if (i < window.i0 || i > window.i1 || j < window.j0 || j > window.j1) return true;
    if (!reduce) return false;
    return i < first_positive || j < first_positive || j > i;
  }
};

// The interval of a normal component c (stored as c·0.5 + 0.5, unorm) that rounds to q.
inline void unorm_interval(std::uint32_t q, int bits, double& lo, double& hi) {
  const double m = unorm_max(bits);
  lo = 2 * (q - 0.5) / m - 1;
  hi = 2 * (q + 0.5) / m - 1;
}
// The least and the largest square over [lo, hi].
inline double min_sq(double lo, double hi) { return lo <= 0 && hi >= 0 ? 0 : std::min(lo * lo, hi * hi); }
inline double max_sq(double lo, double hi) { return std::max(lo * lo, hi * hi); }

// The pieces whose first code coordinate is i, added to `a`.
void planar_pieces(const method& m, int bits, std::uint32_t i, const code_filter& f, acc& a);
// global_lb: the best angle of an earlier run, against which sub-intervals are pruned.
void lambert_pieces(const method& m, int bits, std::uint32_t i, double tol, double global_lb, const code_filter& f,
                    acc& a);

}  // namespace gsdot3::normal_encoding::cell_pieces
