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

// Listing 1 on a fetched (possibly filtered) texel t ∈ [0, 1]³, already in the shader's format.
// The zero-sum case (every N·B_i ≤ 0) gives 0·L/0 = NaN, as the shader does.
constexpr double rnm_diffuse_fetched(const shader_arith& a, const vec3<double>& t, const lightmaps& L,
                                     const basis3& B = source_basis) noexcept {
  const vec3<double> N{a.sub(a.mul(2.0, t.x), 1.0), a.sub(a.mul(2.0, t.y), 1.0), a.sub(a.mul(2.0, t.z), 1.0)};
  auto dp = [&](const vec3<double>& b) {
    const double s = a.saturate(a.dp3(N.x, N.y, N.z, a.r(b.x), a.r(b.y), a.r(b.z)));
    return a.mul(s, s);
  };
  const double d0 = dp(B[0]), d1 = dp(B[1]), d2 = dp(B[2]);
  const double sum = a.dp3(d0, d1, d2, 1.0, 1.0, 1.0);
  const double lit = a.add(a.add(a.mul(d0, L.L0), a.mul(d1, L.L1)), a.mul(d2, L.L2));
  return a.div(lit, sum);
}

// Listing 1 on an 8-bit texel (eq. (2): N = 2·T − 1 after the UNORM8 fetch).
constexpr double rnm_diffuse(const shader_arith& a, const texel& t, const lightmaps& L,
                             const basis3& B = source_basis) noexcept {
  return rnm_diffuse_fetched(a, vec3<double>{unorm8(a, t.r), unorm8(a, t.g), unorm8(a, t.b)}, L, B);
}

// Listing 2 on a fetched (possibly filtered) texel D ∈ [0, 1]³.
constexpr double ssbump_diffuse_fetched(const shader_arith& a, const vec3<double>& D, const lightmaps& L) noexcept {
  return a.add(a.add(a.mul(D.x, L.L0), a.mul(D.y, L.L1)), a.mul(D.z, L.L2));
}

constexpr double ssbump_diffuse(const shader_arith& a, const texel& t, const lightmaps& L) noexcept {
  return ssbump_diffuse_fetched(a, ssbump_weights(a, t), L);
}

// A dynamic light (seed §1.4: "project the lighting direction onto our basis directions and use that
// directly in the lighting equation"): L_i = saturate(B_i·l) for the unit tangent-space direction l.
// With orthonormal B, Σ (B_i·N)(B_i·l) = N·l, so weights proportional to B_i·N light exactly; the
// squared, normalised weights of eq. (3) do not (flat N, l = N: Σ (1/3)(1/√3) = 1/√3).
constexpr lightmaps project_light(const vec3<double>& l, const basis3& B = exact_basis) noexcept {
  auto s = [](double x) { return x < 0 ? 0.0 : x > 1 ? 1.0 : x; };
  return {s(dot(B[0], l)), s(dot(B[1], l)), s(dot(B[2], l))};
}

// Σ D_i·L_i exactly (the reference both are measured against).
constexpr double weighted(const vec3<double>& D, const lightmaps& L) noexcept {
  return D.x * L.L0 + D.y * L.L1 + D.z * L.L2;
}

}  // namespace gsdot3::valve
