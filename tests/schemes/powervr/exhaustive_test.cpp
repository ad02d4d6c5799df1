// tests/schemes/powervr/exhaustive_test.cpp — the identity's 8-bit error over every (S, R) texel ×
// every Q byte × T = 0..90° (15°) × S_l ∈ {1, 0.5} = 65536·256·7·2 = 234 881 024 cases per precision
// option (the catalogue row powervr.identity-8bit runs every 32nd Q), against the a-priori bound.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "bounds.hpp"
#include "proofs/powervr_sweeps.hpp"

namespace gsdot3::schemes::powervr {
namespace {

TEST(PowervrExhaustive, IdentityErrorEveryQWithinTheBound) {
  proofs::powervr_sweeps::identity_grid g;
  for (int q = 0; q < 256; ++q) g.q_bytes.push_back(q);
  for (int t = 0; t <= 90; t += 15) g.elevations.push_back(t * std::numbers::pi / 180.0);
  g.intensities = {1.0, 0.5};
  ASSERT_EQ(g.size(), 234881024ull);
  for (auto a : {azimuth_scale::flycast_255, azimuth_scale::kos_256})
    for (auto p : all_precisions) {
      const auto st = proofs::powervr_sweeps::identity_8bit_error(g, a, p, {});
      ASSERT_EQ(st.n, g.size());
      std::printf("%s %s: %llu cases, max %.6f, mean %.6f, RMSE %.6f (1/255), bound %.6f\n", name(p), name(a),
                  static_cast<unsigned long long>(st.n), st.max_abs, st.mean(), st.rmse(),
                  test::identity_error_bound(p));
      EXPECT_LE(st.max_abs, test::identity_error_bound(p)) << name(p) << " " << name(a);
    }
}

}  // namespace
}  // namespace gsdot3::schemes::powervr
