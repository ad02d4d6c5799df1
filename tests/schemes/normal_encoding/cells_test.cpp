// The rounding-cell argument (cells.hpp) against brute force: at small bit counts (5 and 6 bits,
// cells of several degrees) the supremum must bound every densely sampled direction and be
// approached by one (within the sampling's resolution), the dihedral reduction must give the same
// supremum as the full enumeration, and the witness must really encode to its cell.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "normal_encoding/cells.hpp"
#include "normal_encoding/sampling.hpp"

namespace ne = gsdot3::normal_encoding;

namespace {
constexpr double deg = 180 / std::numbers::pi;

// The largest angle over an area-uniform set (finite decodes only; #8 over z >= 0).
double sampled_max(const ne::method& m, int bits, std::uint64_t n) {
  double best = 0;
  for (std::uint64_t k = 0; k < n; ++k) {
    const ne::vec3 p = ne::fibonacci_point(k, n);
    if (m.front_hemisphere && p.z < 0) continue;
    const ne::vec3 d = m.decode(m.encode(p, bits), bits);
    if (ne::finite(d)) best = std::max(best, ne::angle(d, p) * deg);
  }
  return best;
}
// The largest angle over 2^16 directions in the cap of radius 1° around p (a dense local look at
// the supremum's neighbourhood: suprema at a pole are approached only inside thin slivers there).
double local_max(const ne::method& m, int bits, ne::vec3 p) {
  const ne::vec3 a =
      std::fabs(p.x) < 0.9 ? ne::normalize(ne::cross(p, {1, 0, 0})) : ne::normalize(ne::cross(p, {0, 1, 0}));
  const ne::vec3 b = ne::cross(p, a);
  double best = 0;
  constexpr std::uint64_t n = 65536;
  for (std::uint64_t k = 0; k < n; ++k) {
    const ne::vec3 f = ne::fibonacci_point(k, n);  // map the unit sphere's top cap z >= cos 1° linearly
    const double z = 1 - (1 - f.z) / 2 * (1 - std::cos(1 / deg));
    const double r = std::sqrt(std::max(0.0, 1 - z * z)), phi = std::atan2(f.y, f.x);
    const ne::vec3 q = ne::normalize(z * p + (r * std::cos(phi)) * a + (r * std::sin(phi)) * b);
    if (m.front_hemisphere && q.z < 0) continue;
    const ne::vec3 d = m.decode(m.encode(q, bits), bits);
    if (ne::finite(d)) best = std::max(best, ne::angle(d, q) * deg);
  }
  return best;
}
}  // namespace

TEST(NormalEncodingCells, FarthestPointOfACapAndABox) {
  // The cap z >= cos 10° seen from +z: farthest at 10° (its rim). Seen from −z, −d = +z is in the
  // cap, so the least d·n is −1.
  const auto cap = ne::farthest({0, 0, 1}, {{{0, 0, 1}, std::cos(10 / deg)}});
  ASSERT_TRUE(cap.nonempty);
  EXPECT_NEAR(std::acos(cap.min_dot) * deg, 10, 1e-9);
  const auto opposite = ne::farthest({0, 0, -1}, {{{0, 0, 1}, std::cos(10 / deg)}});
  EXPECT_NEAR(opposite.min_dot, -1, 1e-12);
  // An empty region: z >= 0.5 and z <= 0.4.
  EXPECT_FALSE(ne::farthest({0, 0, 1}, {{{0, 0, 1}, 0.5}, {{0, 0, -1}, -0.4}}).nonempty);
  // The box x, y ∈ [0, 0.1], z > 0 seen from +z: farthest at its corner (0.1, 0.1, sqrt(0.98)).
  const auto box =
      ne::farthest({0, 0, 1}, {{{1, 0, 0}, 0}, {{-1, 0, 0}, -0.1}, {{0, 1, 0}, 0}, {{0, -1, 0}, -0.1}, {{0, 0, 1}, 0}});
  EXPECT_NEAR(box.min_dot, std::sqrt(0.98), 1e-12);
}

class SmallBits : public ::testing::TestWithParam<int> {};

TEST_P(SmallBits, SupremumBoundsAndIsApproachedByDenseSampling) {
  const int bits = GetParam();
  constexpr std::uint64_t samples = std::uint64_t{1} << 20;  // spacing ~ 0.2°
  const double resolution_deg = 0.25;
  for (const auto& m : ne::methods()) {
    if (m.only_8_bits || m.id == ne::method_id::octahedral_precise) continue;
    const auto w = ne::cell_worst_case(m, bits, 2);
    const double s = sampled_max(m, bits, samples);
    EXPECT_LE(s, w.upper_deg + 1e-9) << m.name << " at " << bits << " bits";
    EXPECT_GE(std::max(s, local_max(m, bits, w.n)), w.sup_deg - resolution_deg) << m.name << " at " << bits << " bits";
    // The witness encodes to the worst cell, and its angle is the supremum (or approaches it).
    const double wa = ne::angle(m.decode(m.encode(w.witness, bits), bits), w.witness) * deg;
    EXPECT_EQ(m.encode(w.witness, bits), w.q) << m.name;
    EXPECT_NEAR(wa, w.sup_deg, 1e-3) << m.name;
  }
}

TEST_P(SmallBits, DihedralReductionMatchesFullEnumeration) {
  const int bits = GetParam();
  for (const auto& m : ne::methods()) {
    if (m.only_8_bits) continue;
    const auto reduced = ne::cell_worst_case(m, bits, 2, ne::default_tolerance_rad, true);
    const auto full = ne::cell_worst_case(m, bits, 2, ne::default_tolerance_rad, false);
    EXPECT_NEAR(reduced.sup_deg, full.sup_deg, 1e-9) << m.name;
    EXPECT_EQ(reduced.nonfinite_cells > 0, full.nonfinite_cells > 0) << m.name;
  }
}

INSTANTIATE_TEST_SUITE_P(NormalEncoding, SmallBits, ::testing::Values(5, 6));

TEST(NormalEncodingCells, AWindowIsTheSupOverItsCellsOnly) {
  // The whole range as a window is the full enumeration; a window around the worst cell keeps its
  // supremum; a window away from it gives less (a lower bound, as the 2×16 row is reported).
  const auto& m = ne::method_named("octahedral");
  const auto full = ne::cell_worst_case(m, 6, 2, ne::default_tolerance_rad, false);
  const auto all = ne::cell_worst_case(m, 6, 2, ne::default_tolerance_rad, false, ne::code_window{0, 63, 0, 63});
  EXPECT_DOUBLE_EQ(all.sup_deg, full.sup_deg);
  const ne::code_window around{full.q.c[0] - 2, full.q.c[0] + 2, full.q.c[1] - 2, full.q.c[1] + 2};
  EXPECT_DOUBLE_EQ(ne::cell_worst_case(m, 6, 2, ne::default_tolerance_rad, false, around).sup_deg, full.sup_deg);
  const ne::code_window centre{30, 33, 30, 33};  // around +z, far from the worst cell near (1, 1, −1)/√3
  EXPECT_LT(ne::cell_worst_case(m, 6, 2, ne::default_tolerance_rad, false, centre).sup_deg, full.sup_deg);
}
