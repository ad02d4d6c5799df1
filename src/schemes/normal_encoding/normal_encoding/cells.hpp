// normal_encoding/cells.hpp — the worst case over the whole sphere, from the rounding cells.
//
// Argument. The cell of a code q is the set of unit n that encode to q. The angle to a fixed unit d
// has no local maximum on the sphere except at −d, so over a closed cell not containing −d its
// supremum lies on the cell's boundary (and equals the supremum over the cell's interior, the angle
// being continuous: half-open rounding intervals and sign(0) conventions do not change it).
//  * Planar methods — xyz, #1, #2, #3, #3a, #7, #8, octahedral (per octant): every cell boundary is
//    on a plane (x = c; a meridian φ = c; x = c·(1 + z); x = c·(|x| + |y| + |z|) within an octant), so
//    a cell (piece) is the sphere ∩ a convex polyhedron {a_k·n >= b_k}. The minimum of d·n over it is
//    at −d if feasible, or at the minimum of d·n on one face circle (closed form) if feasible, or at a
//    vertex (sphere ∩ two planes). All candidates are evaluated: the supremum is exact up to double
//    rounding (tolerance 1e-12 in the feasibility test).
//  * Lambert family — #4, #5, #6 (same mapping for unit n): a cell is L(square ∩ disk |a| <= 1/2)
//    with L(a) = (4a·sqrt(1 − 4|a|²), 1 − 8|a|²); its boundary is L(square edges) plus, when the square
//    meets the circle |a| = 1/2, the south pole. On each edge the angle is maximised by branch and
//    bound: on a sub-interval it is at most (end values' mean) + K·h/2, K = 4/sqrt(1 − 4r²_max) the
//    largest singular value of dL (r = |a|), and at most angle(d, south pole) + (π − θ(r_min)),
//    θ(r) = 2·asin(2r); sub-intervals are split until their bound is within `tolerance_rad` of the
//    best value found. The result is an interval [sup_deg, upper_deg] of width <= the tolerance.
// Cells whose code decodes to NaN/Inf are counted separately (their n are reachable and broken).
#pragma once

#include <cstdint>
#include <vector>

#include "normal_encoding/methods.hpp"

namespace gsdot3::normal_encoding {

struct halfspace {
  vec3 a;    // unit normal
  double b;  // a·n >= b
};
struct farthest_point {
  bool nonempty = false;
  double min_dot = 2;  // least d·n over the region
  vec3 p{};            // where
};
// The point of sphere ∩ {a_k·n >= b_k} farthest from the unit direction d (see above). The a_k
// need not be unit on input (they are normalised here).
farthest_point farthest(vec3 d, std::vector<halfspace> h);

struct worst_case {
  double sup_deg = 0;                 // the supremum of the angle over cells with a finite decode
  double upper_deg = 0;               // certified upper bound (= sup_deg for the planar methods)
  vec3 n{};                           // a point of the closure of the worst cell that attains sup_deg
  code q{};                           // that cell's code
  std::uint64_t cells = 0;            // non-empty cells (or cell pieces) enumerated
  std::uint64_t nonfinite_cells = 0;  // non-empty cells whose code decodes to NaN/Inf
  vec3 nonfinite_n{};                 // a point inside the first such cell
  code nonfinite_q{};
  vec3 witness{};  // a unit n near `n` that encodes to q (its angle approaches sup_deg)
  bool branch_and_bound = false;
  bool reduced = false;  // enumerated 1/8 of the codes by the dihedral symmetry
};

// Every cell of m at `bits` (whole sphere; #8 its front hemisphere z >= 0). Octahedral-precise is
// not a rounding-cell method: use octahedral's (its upper bound, since the nearest code is among the
// four tried). Threads split the first code coordinate.
inline constexpr double default_tolerance_rad = 1e-10;
// A rectangle of codes (channels 0 and 1, inclusive) to enumerate instead of all: the result is then
// the supremum over those cells only, a lower bound for the whole sphere (used at 2×16).
struct code_window {
  std::uint32_t i0 = 0, i1 = 0xFFFFFFFFu, j0 = 0, j1 = 0xFFFFFFFFu;
};
// use_symmetry: enumerate only the codes i >= j >= the first positive code, for the methods that
// commute with the reflections x -> −x, y -> −y and the swap x <-> y (cells.cpp).
worst_case cell_worst_case(const method& m, int bits, unsigned threads = 2,
                           double tolerance_rad = default_tolerance_rad, bool use_symmetry = true,
                           code_window window = {});

}  // namespace gsdot3::normal_encoding
