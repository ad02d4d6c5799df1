// tests/schemes/valve/property_test.cpp — laws of the two shader paths (rapidcheck).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "valve/decode.hpp"
#include "valve/encode.hpp"
#include "valve/evaluate.hpp"

namespace gsdot3::valve {
namespace {

double unit_interval(int k) { return (k % 100001) / 100000.0; }

// SSBump evaluation is linear in the texel weights: filtering (any convex combination, e.g. the
// bilinear and mip-map averages) commutes with lighting.
RC_GTEST_PROP(ValveProperty, SsbumpEvaluationIsLinear, ()) {
  const auto a = *rc::gen::container<std::vector<int>>(9, rc::gen::inRange(0, 100001));
  const vec3<double> D{unit_interval(a[0]), unit_interval(a[1]), unit_interval(a[2])};
  const vec3<double> E{unit_interval(a[3]), unit_interval(a[4]), unit_interval(a[5])};
  const lightmaps L{unit_interval(a[6]) * 4, unit_interval(a[7]) * 4, unit_interval(a[8]) * 4};
  const double w = *rc::gen::inRange(0, 17) / 16.0;
  const vec3<double> F{(1 - w) * D.x + w * E.x, (1 - w) * D.y + w * E.y, (1 - w) * D.z + w * E.z};
  RC_ASSERT(std::fabs(weighted(F, L) - ((1 - w) * weighted(D, L) + w * weighted(E, L))) < 1e-12);
}

// Σ D_i = 1 wherever eq. (3) is defined, exactly (double) and in the shader with unit lightmaps.
RC_GTEST_PROP(ValveProperty, WeightsSumToOneWhereDefined, ()) {
  const texel t{*rc::gen::arbitrary<std::uint8_t>(), *rc::gen::arbitrary<std::uint8_t>(),
                *rc::gen::arbitrary<std::uint8_t>()};
  vec3<double> D;
  if (!exact_weights(normalised(encoded_normal(t)), D)) {
    RC_ASSERT(std::isnan(rnm_diffuse(shader_arith{precision::fp32}, t, {1, 0, 0})));
    return;
  }
  RC_ASSERT(std::fabs(D.x + D.y + D.z - 1.0) < 1e-15);
  const shader_arith a{precision::fp32};
  const double s = rnm_diffuse(a, t, {1, 0, 0}) + rnm_diffuse(a, t, {0, 1, 0}) + rnm_diffuse(a, t, {0, 0, 1});
  RC_ASSERT(std::fabs(s - 1.0) < 1e-6);
  const vec3<float> n = normal2ssbump(t);
  RC_ASSERT(std::fabs(n.x + n.y + n.z - 1.0f) < 1e-6f);
}

// The weights do not depend on the texel normal's length (up to saturate), so normalising first
// changes nothing as long as every N·B_i ≤ 1.
RC_GTEST_PROP(ValveProperty, WeightsAreScaleInvariant, ()) {
  const texel t{*rc::gen::arbitrary<std::uint8_t>(), *rc::gen::arbitrary<std::uint8_t>(),
                *rc::gen::arbitrary<std::uint8_t>()};
  const vec3<double> N = encoded_normal(t), U = normalised(N);
  vec3<double> D, E;
  RC_PRE(dot(N, exact_basis[0]) <= 1 && dot(N, exact_basis[1]) <= 1 && dot(N, exact_basis[2]) <= 1);
  RC_PRE(exact_weights(N, D));
  RC_ASSERT(exact_weights(U, E));
  RC_ASSERT(std::fabs(D.x - E.x) < 1e-12 && std::fabs(D.y - E.y) < 1e-12 && std::fabs(D.z - E.z) < 1e-12);
}

}  // namespace
}  // namespace gsdot3::valve
