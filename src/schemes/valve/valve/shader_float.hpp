// valve/shader_float.hpp — the arithmetic a DX9 pixel shader evaluates the seed's listings in.
//
// Each operation (mul, add, rcp) is computed exactly in double and then rounded to the shader's
// float format, so each step is correctly rounded: double holds ≥ 2p + 2 bits for p = 24 and
// p = 17, so rounding the double result again introduces no double-rounding error for +, −, ×, ÷.
//  - fp32: IEEE binary32, round to nearest even (NVIDIA NV3x and later; "NVIDIA GPUs supporting
//    ps_2_0 use standard IEEE 754 single-precision", NVIDIA Cg ps_2_0 profile documentation,
//    developer.download.nvidia.com/cg/ps_2_0.html).
//  - fp24: s16e7 — sign, 7-bit exponent, 16 stored mantissa bits (17 significant). Direct3D 9's
//    ps_2_0 full precision is "fp24=s16e7 or higher" (Microsoft, "Shader model 3 (HLSL reference)",
//    table "Specifying Full or Partial Precision"), and "older ATI GPUs use 24-bit floating-point"
//    (NVIDIA Cg ps_2_0 profile documentation) — the R300 family. The rounding mode of the R300's
//    fp24 is not public: round to nearest even is an ASSUMPTION, named as such in every figure.
//    Exponent range (bias 63) is not modelled: every value here lies in [2^-40, 4] or is 0.
//  - exact: no rounding (the double reference).
#pragma once

#include <bit>
#include <cstdint>
#include <string_view>

namespace gsdot3::valve {

enum class precision { exact, fp32, fp24 };

constexpr std::string_view name(precision p) noexcept {
  return p == precision::exact ? "exact" : p == precision::fp32 ? "fp32" : "fp24";
}

// Round a double to 17 significant bits, ties to even (s16e7's significand).
constexpr double round_fp24(double x) noexcept {
  constexpr int dropped = 52 - 16;  // double keeps 52 stored bits, s16e7 keeps 16
  std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t lsb = (bits >> dropped) & 1U;
  bits += (std::uint64_t{1} << (dropped - 1)) - 1 + lsb;  // carries into the exponent as it should
  bits &= ~((std::uint64_t{1} << dropped) - 1);
  return std::bit_cast<double>(bits);
}

constexpr double rounded(precision p, double x) noexcept {
  switch (p) {
    case precision::fp32: return static_cast<double>(static_cast<float>(x));
    case precision::fp24: return round_fp24(x);
    case precision::exact: break;
  }
  return x;
}

// One shader's arithmetic: every result rounded to p.
struct shader_arith {
  precision p = precision::fp32;
  constexpr double r(double x) const noexcept { return rounded(p, x); }
  constexpr double mul(double a, double b) const noexcept { return r(a * b); }
  constexpr double add(double a, double b) const noexcept { return r(a + b); }
  constexpr double sub(double a, double b) const noexcept { return r(a - b); }
  // ps_2_0 has no divide instruction: a / b is rcp then mul (rcp assumed correctly rounded).
  constexpr double div(double a, double b) const noexcept { return p == precision::exact ? a / b : mul(a, r(1.0 / b)); }
  constexpr double saturate(double a) const noexcept { return a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a; }
  constexpr double dp3(double ax, double ay, double az, double bx, double by, double bz) const noexcept {
    return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz));
  }
};

}  // namespace gsdot3::valve
