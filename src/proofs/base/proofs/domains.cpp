#include "proofs/domains.hpp"

#include <cmath>
#include <stdexcept>

namespace gsdot3::proofs {

namespace {
// The float of least magnitude whose product with 127.9f truncates to i (i != 0), searching from
// i / 127.9 by single ulps; 0 for i = 0.
float least_float_for(int i) {
  if (i == 0) return 0.0f;
  const float scale = 127.9f;
  const float toward = i > 0 ? 0.0f : -0.0f;
  float x = static_cast<float>(static_cast<double>(i) / 127.9);
  while ((int)(x * scale) != i) x = std::nextafter(x, i > 0 ? 2.0f : -2.0f);
  for (float y = std::nextafter(x, toward); (int)(y * scale) == i; y = std::nextafter(y, toward)) x = y;
  return x;
}
}  // namespace

const std::vector<paper::packed_normal>& appendix2_normals() {
  static const std::vector<paper::packed_normal> all = [] {
    std::vector<paper::packed_normal> out;
    for (int iX = -127; iX <= 127; ++iX)
      for (int iY = -127; iY <= 127; ++iY) {
        if (iX * iX + iY * iY > 16358) continue;
        const float nx = least_float_for(iX), ny = least_float_for(iY);
        const double r2 = static_cast<double>(nx) * nx + static_cast<double>(ny) * ny;
        if (r2 > 1.0) throw std::logic_error("appendix2_normals: pair not reachable by a unit normal");
        out.push_back(paper::pack_normal(nx, ny));
      }
    return out;
  }();
  return all;
}

bool is_packed_light(int s, const ivec3& l) noexcept {
  const int near = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
  const int ax = std::abs(l[0]) + 1, ay = std::abs(l[1]) + 1, az = std::abs(l[2]) + 1;
  return near <= s * s && s * s < ax * ax + ay * ay + az * az;
}

std::vector<ivec3> attenuated_lights(int s) {
  std::vector<ivec3> out;
  for (int x = -s; x <= s; ++x)
    for (int y = -s; y <= s; ++y)
      for (int z = -s; z <= s; ++z)
        if (x * x + y * y + z * z <= s * s) out.push_back({x, y, z});
  return out;
}

std::vector<ivec3> packed_lights(int s) {
  std::vector<ivec3> out;
  for (int x = -s; x <= s; ++x)
    for (int y = -s; y <= s; ++y)
      for (int z = -s; z <= s; ++z)
        if (is_packed_light(s, {x, y, z})) out.push_back({x, y, z});
  return out;
}

std::vector<ivec3> normal_map_vectors(bool full_sphere) {
  std::vector<ivec3> out;
  const int r4 = 4 * 127 * 127;
  auto lo = [](int b) {
    const int v = 2 * std::abs(b) - 1;
    return v > 0 ? v * v : 0;
  };
  auto hi = [](int b) {
    const int v = 2 * std::abs(b) + 1;
    return v * v;
  };
  for (int x = -127; x <= 127; ++x)
    for (int y = -127; y <= 127; ++y)
      for (int z = full_sphere ? -127 : 0; z <= 127; ++z)
        if (lo(x) + lo(y) + lo(z) <= r4 && r4 <= hi(x) + hi(y) + hi(z)) out.push_back({x, y, z});
  return out;
}

std::vector<ivec3> sphere_map_vectors(int size) {
  std::vector<ivec3> out;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto t = paper::sphere_map_texel(x, y, size, size);
      out.push_back({128 - t.r, 128 - t.g, 128 - t.b});
    }
  return out;
}

}  // namespace gsdot3::proofs
