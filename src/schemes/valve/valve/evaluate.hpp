// valve/evaluate.hpp — the pixel shader's diffuse lighting from the three lightmap values L0..L2:
// Listing 1 (RNM: the normal texel, eq. (2)-(4), d = saturate(N·B)², Σ d_i·L_i / Σ d) and Listing 2
// (SSBump: Σ t_i·L_i), in a shader's arithmetic (shader_float.hpp), with the basis constants in the
// shader's format.
#pragma once

#include "valve/basis.hpp"
#include "valve/decode.hpp"
#include "valve/shader_float.hpp"

namespace gsdot3::valve {

struct lightmaps {
  double L0 = 0, L1 = 0, L2 = 0;
};

// Listing 1. The zero-sum case (every N·B_i ≤ 0) gives 0·L/0 = NaN, as the shader does.
constexpr double rnm_diffuse(const shader_arith& a, const texel& t, const lightmaps& L, const basis3& B = source_basis) noexcept {
  const vec3<double> N = rnm_normal(a, t);
  auto dp = [&](const vec3<double>& b) {
    const double s = a.saturate(a.dp3(N.x, N.y, N.z, a.r(b.x), a.r(b.y), a.r(b.z)));
    return a.mul(s, s);
  };
  const double d0 = dp(B[0]), d1 = dp(B[1]), d2 = dp(B[2]);
  const double sum = a.dp3(d0, d1, d2, 1.0, 1.0, 1.0);
  const double lit = a.add(a.add(a.mul(d0, L.L0), a.mul(d1, L.L1)), a.mul(d2, L.L2));
  return a.div(lit, sum);
}

// Listing 2.
constexpr double ssbump_diffuse(const shader_arith& a, const texel& t, const lightmaps& L) noexcept {
  const vec3<double> D = ssbump_weights(a, t);
  return a.add(a.add(a.mul(D.x, L.L0), a.mul(D.y, L.L1)), a.mul(D.z, L.L2));
}

// Σ D_i·L_i exactly (the reference both are measured against).
constexpr double weighted(const vec3<double>& D, const lightmaps& L) noexcept { return D.x * L.L0 + D.y * L.L1 + D.z * L.L2; }

}  // namespace gsdot3::valve
