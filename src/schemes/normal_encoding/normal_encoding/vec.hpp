// normal_encoding/vec.hpp — the double-precision 3-vector every encoding takes and returns.
// The encodings are evaluated in double (the seed's shaders run in float; the difference is far below
// one code step at 16 bits and is stated where a figure depends on it).
#pragma once

#include <cmath>

namespace gsdot3::normal_encoding {

struct vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const vec3&, const vec3&) = default;
};

constexpr vec3 operator+(vec3 a, vec3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr vec3 operator-(vec3 a, vec3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr vec3 operator*(double s, vec3 a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
constexpr double dot(vec3 a, vec3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr vec3 cross(vec3 a, vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(vec3 a) noexcept { return std::sqrt(dot(a, a)); }
// HLSL normalize: v · rsqrt(dot(v, v)); the zero vector gives NaN (0 · inf), as on the GPU.
inline vec3 normalize(vec3 a) noexcept { return (1.0 / length(a)) * a; }
inline bool finite(vec3 a) noexcept { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

// The angle between the directions of a and b in radians, accurate also for tiny angles
// (atan2 of |a × b| and a · b); NaN if either is non-finite or zero.
inline double angle(vec3 a, vec3 b) noexcept {
  if (!finite(a) || !finite(b) || dot(a, a) == 0 || dot(b, b) == 0) return std::nan("");
  return std::atan2(length(cross(a, b)), dot(a, b));
}

}  // namespace gsdot3::normal_encoding
