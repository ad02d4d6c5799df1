// pipeline/mesh_duplicates.cpp — duplicated triangles found and dropped (see mesh_duplicates.hpp).
#include "pipeline/mesh_duplicates.hpp"
#include "pipeline/word_hash.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <unordered_set>

namespace gsdot3::pipeline {

namespace {

using position_key = std::array<std::uint32_t, 3>;
using triangle_key = std::array<std::uint32_t, 9>;

using key_hash = word_hash;

position_key key_of(glm::vec3 p) {
  auto word = [](float f) { return std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f); };
  return {word(p.x), word(p.y), word(p.z)};
}

// The three positions rotated to start at the smallest: equal for the same triangle whichever corner
// the file starts it at, different for the opposite winding.
triangle_key key_of(const mesh& m, const std::array<std::uint32_t, 3>& t) {
  const std::array<position_key, 3> p{key_of(m.vertices[t[0]].position), key_of(m.vertices[t[1]].position),
                                      key_of(m.vertices[t[2]].position)};
  const std::size_t first = static_cast<std::size_t>(std::min_element(p.begin(), p.end()) - p.begin());
  triangle_key k{};
  for (std::size_t i = 0; i < 3; ++i)
    std::copy(p[(first + i) % 3].begin(), p[(first + i) % 3].end(), k.begin() + 3 * i);
  return k;
}

}  // namespace

std::size_t find_duplicate_triangles(mesh& m, bool drop) {
  std::unordered_set<triangle_key, key_hash> seen;
  std::size_t found = 0, kept = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const bool fresh = seen.insert(key_of(m, m.triangles[t])).second;
    found += !fresh;
    if (fresh || !drop) {
      if (!m.layer.empty()) m.layer[kept] = m.layer[t];
      m.triangles[kept++] = m.triangles[t];
    }
  }
  m.triangles.resize(kept);
  if (!m.layer.empty()) m.layer.resize(kept);
  return found;
}

}  // namespace gsdot3::pipeline
