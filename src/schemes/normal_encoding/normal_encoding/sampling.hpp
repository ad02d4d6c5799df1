// normal_encoding/sampling.hpp — an area-uniform set of directions: the spherical Fibonacci lattice
// of N points, z_k = 1 − (2k + 1)/N, φ_k = 2π·frac(k·(√5 − 1)/2). Each point stands for an equal-area
// band slice (Archimedes: z uniform <=> area uniform), so means over it are area-weighted means.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding {

inline vec3 fibonacci_point(std::uint64_t k, std::uint64_t n) noexcept {
  const double z = 1 - (2.0 * static_cast<double>(k) + 1) / static_cast<double>(n);
  const double golden = (std::sqrt(5.0) - 1) / 2;
  const double f = static_cast<double>(k) * golden;
  const double phi = 2 * std::numbers::pi * (f - std::floor(f));
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace gsdot3::normal_encoding
