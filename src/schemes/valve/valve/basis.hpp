// valve/basis.hpp — the three tangent-space directions of Radiosity Normal Mapping (seed 001,
// C. Green, "Efficient Self-Shadowed Radiosity Normal Mapping", 2007), in three forms:
//  - exact: the real vectors of Source's g_localBumpBasis (ValveSoftware/source-sdk-2013,
//    src/public/mathlib/bumpvects.h), here as the nearest doubles; their exact values live in
//    q23.hpp (the field Q(√2, √3)) for the proofs;
//  - shipped: the float literals of Source's shaders and tools (common_fxc.h bumpBasis, read in
//    the stored source-sdk-2013 copy, and normal2ssbump.cpp, which repeats them): 1/√6 appears
//    twice with different values, 0.40824833512306213 in B1 and 0.40824821591377258 in B2;
//  - printed: the seed's equation (1) as printed (misprinted: B0 = B1, and B2 = (−√2/√3, 0, 1/√3)).
// Order B0, B1, B2 as Source writes them; the paper's figure orders them B1, B2, B0.
#pragma once

#include <array>

namespace gsdot3::valve {

template <class T>
struct vec3 {
  T x{}, y{}, z{};
  friend constexpr bool operator==(const vec3&, const vec3&) = default;
};

// The dot product in the order a DX9 dp3 is written: (x·x + y·y) + z·z.
template <class T>
constexpr T dot(const vec3<T>& a, const vec3<T>& b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

using basis3 = std::array<vec3<double>, 3>;

// √(2/3), 1/√2, 1/√3, 1/√6 to 17 significant digits (nearest doubles; pinned against std::sqrt
// in tests/schemes/valve).
inline constexpr double sqrt_2_3 = 0.81649658092772603;
inline constexpr double inv_sqrt2 = 0.70710678118654752;
inline constexpr double inv_sqrt3 = 0.57735026918962576;
inline constexpr double inv_sqrt6 = 0.40824829046386302;

inline constexpr basis3 exact_basis = {{
    {sqrt_2_3, 0.0, inv_sqrt3},
    {-inv_sqrt6, inv_sqrt2, inv_sqrt3},
    {-inv_sqrt6, -inv_sqrt2, inv_sqrt3},
}};

// Source's float literals (common_fxc.h: bumpBasis; OO_SQRT_3 = 0.57735025882720947f).
inline constexpr std::array<vec3<float>, 3> source_basis_float = {{
    {0.81649661064147949f, 0.0f, 0.57735025882720947f},
    {-0.40824833512306213f, 0.70710676908493042f, 0.57735025882720947f},
    {-0.40824821591377258f, -0.7071068286895752f, 0.57735025882720947f},
}};

constexpr basis3 widen(const std::array<vec3<float>, 3>& b) noexcept {
  basis3 out{};
  for (int i = 0; i < 3; ++i)
    out[static_cast<unsigned>(i)] = {b[static_cast<unsigned>(i)].x, b[static_cast<unsigned>(i)].y,
                                     b[static_cast<unsigned>(i)].z};
  return out;
}
inline constexpr basis3 source_basis = widen(source_basis_float);

// The exact basis rounded to float (via the nearest double; no double-rounding case arises for these
// four constants — pinned in tests/schemes/valve).
inline constexpr std::array<vec3<float>, 3> exact_basis_float = {{
    {static_cast<float>(sqrt_2_3), 0.0f, static_cast<float>(inv_sqrt3)},
    {static_cast<float>(-inv_sqrt6), static_cast<float>(inv_sqrt2), static_cast<float>(inv_sqrt3)},
    {static_cast<float>(-inv_sqrt6), static_cast<float>(-inv_sqrt2), static_cast<float>(inv_sqrt3)},
}};

// bumpvects.h's g_localBumpBasis in float: built from mathlib.h's OO_SQRT_2_OVER_3, OO_SQRT_6,
// OO_SQRT_2, OO_SQRT_3 defines, so B1 and B2 share 0.40824821591377258f (read in stored ports of
// those defines, not in Valve's own bumpvects.h). height2ssbump's library uses this one.
inline constexpr std::array<vec3<float>, 3> bumpvects_basis_float = {{
    {0.81649661064147949f, 0.0f, 0.57735025882720947f},
    {-0.40824821591377258f, 0.70710676908493042f, 0.57735025882720947f},
    {-0.40824821591377258f, -0.70710676908493042f, 0.57735025882720947f},
}};

// Equation (1) of the seed as printed: {−1/√6, 1/√2, 1/√3}, {−1/√6, 1/√2, 1/√3}, {−√2/√3, 0, 1/√3}.
inline constexpr basis3 printed_basis = {{
    {-inv_sqrt6, inv_sqrt2, inv_sqrt3},
    {-inv_sqrt6, inv_sqrt2, inv_sqrt3},
    {-sqrt_2_3, 0.0, inv_sqrt3},
}};

}  // namespace gsdot3::valve
