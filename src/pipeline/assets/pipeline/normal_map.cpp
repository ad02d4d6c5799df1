// pipeline/normal_map.cpp — height field to normals; spherical k-means to a 256-entry palette.
#include "pipeline/normal_map.hpp"

#include <algorithm>
#include <limits>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>

namespace gsdot3::pipeline {

std::vector<glm::vec3> normals_from_height(const std::vector<float>& h, int w, int hgt, float strength) {
  std::vector<glm::vec3> out(static_cast<std::size_t>(w) * hgt);
  auto at = [&](int x, int y) { return h[static_cast<std::size_t>((y + hgt) % hgt) * w + (x + w) % w]; };
  for (int y = 0; y < hgt; ++y)
    for (int x = 0; x < w; ++x) {
      const float dx = (at(x + 1, y) - at(x - 1, y)) * 0.5f * strength;
      const float dy = (at(x, y + 1) - at(x, y - 1)) * 0.5f * strength;
      out[static_cast<std::size_t>(y) * w + x] = glm::normalize(glm::vec3(-dx, -dy, 1.0f));
    }
  return out;
}

namespace {

// The distinct normals with their multiplicities (procedural maps repeat a few values a lot).
struct weighted {
  glm::vec3 n;
  double weight;
};

std::vector<weighted> distinct(const std::vector<glm::vec3>& normals) {
  std::map<std::tuple<float, float, float>, double> count;
  for (const glm::vec3& n : normals) count[{n.x, n.y, n.z}] += 1.0;
  std::vector<weighted> out;
  out.reserve(count.size());
  for (const auto& [k, c] : count) out.push_back({{std::get<0>(k), std::get<1>(k), std::get<2>(k)}, c});
  return out;
}

// The palette's centres in blocks of four (x, y, z as 4-lane vectors: GCC / clang vector extensions,
// SSE2 on x86-64), so that the dot products of one normal with four centres are one vector
// expression. Each lane computes (x·x' + y·y') + z·z', the same float operations in the same order as
// glm::dot, so the choice is the same as one dot product at a time (property_test checks it against
// glm::dot, first entry on ties). The last block is padded with NaN centres, which `>` and `==` never
// choose.
class centre_set {
  using f32x4 = float __attribute__((vector_size(16)));
  struct block {
    f32x4 x, y, z, dot;
  };

 public:
  explicit centre_set(const std::vector<glm::vec3>& c) : blocks_((c.size() + 3) / 4) {
    const glm::vec3 pad(std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = 0; i < 4 * blocks_.size(); ++i) {
      const glm::vec3 v = i < c.size() ? c[i] : pad;
      block& b = blocks_[i / 4];
      b.x[i % 4] = v.x, b.y[i % 4] = v.y, b.z[i % 4] = v.z;
    }
  }
  // The first centre of largest dot product with n (0 when every product is NaN): the largest
  // product over four lanes (a maximum does not depend on the order; `>` skips NaNs), then the first
  // block holding it and its first lane there.
  std::size_t nearest(glm::vec3 n) {
    f32x4 lanes = {-2.0f, -2.0f, -2.0f, -2.0f};
    for (block& b : blocks_) {
      b.dot = b.x * n.x + b.y * n.y + b.z * n.z;
      lanes = b.dot > lanes ? b.dot : lanes;
    }
    const float best = std::max({lanes[0], lanes[1], lanes[2], lanes[3]});
    for (std::size_t i = 0; i < blocks_.size(); ++i)
      for (std::size_t j = 0; j < 4; ++j)
        if (blocks_[i].dot[j] == best) return 4 * i + j;
    return 0;
  }

 private:
  std::vector<block> blocks_;
};

}  // namespace

normal_map quantise(const std::vector<glm::vec3>& normals, int width, int height, int entries) {
  if (normals.size() != static_cast<std::size_t>(width) * height || normals.empty())
    throw std::runtime_error("normal map size does not match its data");
  const std::vector<weighted> pts = distinct(normals);
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(entries), pts.size());

  // Farthest-point seeding: each new centre is the point least similar to every centre so far.
  std::vector<glm::vec3> centres{pts.front().n};
  std::vector<float> best(pts.size(), -2.0f);
  while (centres.size() < k) {
    std::size_t pick = 0;
    float lowest = 2.0f;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      best[i] = std::max(best[i], glm::dot(pts[i].n, centres.back()));
      if (best[i] < lowest) lowest = best[i], pick = i;
    }
    centres.push_back(pts[pick].n);
  }

  std::vector<std::size_t> assign(pts.size(), k);
  for (int iter = 0; iter < 30; ++iter) {
    bool changed = false;
    centre_set set(centres);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::size_t c = set.nearest(pts[i].n);
      changed |= c != assign[i];
      assign[i] = c;
    }
    if (!changed) break;
    std::vector<glm::dvec3> sum(k, glm::dvec3(0.0));
    for (std::size_t i = 0; i < pts.size(); ++i) sum[assign[i]] += glm::dvec3(pts[i].n) * pts[i].weight;
    for (std::size_t c = 0; c < k; ++c)
      if (glm::length(sum[c]) > 0.0) centres[c] = glm::vec3(glm::normalize(sum[c]));
  }

  normal_map m;
  m.width = width;
  m.height = height;
  m.palette = centres;
  m.index.resize(normals.size());
  centre_set set(centres);
  for (std::size_t i = 0; i < normals.size(); ++i) m.index[i] = static_cast<std::uint8_t>(set.nearest(normals[i]));
  m.unquantised = normals;
  return m;
}

normal_map with_index_bits(const normal_map& m, int bits) {
  if (bits != 4 && bits != 8 && bits != 24)
    throw std::invalid_argument("normal map bits: 4, 8 or 24, not " + std::to_string(bits));
  if (m.bits == bits) return m;
  if (layers(m) > 1) {  // each layer (a material's map) on its own palette
    std::vector<normal_map> each;
    for (std::size_t k = 0; k < layers(m); ++k) each.push_back(with_index_bits(layer_map(m, k), bits));
    return stacked(each);
  }
  if (bits == 24 && (m.bits != 8 || m.unquantised.size() != m.index.size()))
    throw std::invalid_argument(
        "normal map bits: 24 needs an 8-bit map with its unquantised normals (quantise keeps them)");
  if (bits != 4) {
    normal_map wide = m;
    wide.bits = bits;
    return wide;
  }
  std::vector<glm::vec3> normals(m.index.size());
  for (std::size_t i = 0; i < normals.size(); ++i) normals[i] = m.palette[m.index[i]];
  normal_map narrow = quantise(normals, m.width, m.height, 16);
  narrow.unquantised = m.unquantised;  // what the 8-bit map was quantised from
  narrow.bits = 4;
  return narrow;
}

}  // namespace gsdot3::pipeline
