// split_for_lod (pipeline/lod.hpp, section 3.8): each light's colour split into a per-pixel share and
// a Gouraud rest that add up to it exactly, the share rounded to nearest (halves away from zero),
// checked against exact integer arithmetic for shares that are exact binary fractions; a light at 0
// is left out; a share outside [0, 1] is an error. with_index_bits (pipeline/normal_map.hpp, section
// 3.8's 4-bit maps): 16 unit entries, every texel on a nearest one (brute force over glm::dot).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/normal_map.hpp"

namespace gsdot3::pipeline {
namespace {

scene_light light(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return {{1.0f, 2.0f, 3.0f}, {r, g, b}, light_kind::directional};
}

TEST(LevelOfDetail, SharesOfEveryColourAgainstIntegerRounding) {
  for (const auto& [p, q] : {std::pair{1, 4}, std::pair{1, 2}, std::pair{3, 4}, std::pair{3, 8}, std::pair{5, 8}})
    for (int c = 1; c < 256; ++c) {
      const auto u = static_cast<std::uint8_t>(c);
      const std::vector<scene_light> out = split_for_lod({light(u, u, 0)}, static_cast<double>(p) / q);
      const int dot3 = (2 * p * c + q) / (2 * q);  // floor(c·p/q + 1/2)
      const std::size_t pairs = (dot3 != 0) + (c - dot3 != 0);
      ASSERT_EQ(out.size(), pairs) << p << "/" << q << " of " << c;
      if (dot3 != 0) {
        EXPECT_FALSE(out[0].gouraud);
        EXPECT_EQ(out[0].colour[0], dot3) << p << "/" << q << " of " << c;
        EXPECT_EQ(out[0].colour[2], 0);
        EXPECT_EQ(out[0].kind, light_kind::directional);
        EXPECT_EQ(out[0].position, glm::vec3(1.0f, 2.0f, 3.0f));
      }
      if (c - dot3 != 0) {
        EXPECT_TRUE(out.back().gouraud);
        EXPECT_EQ(out.back().colour[1], c - dot3) << p << "/" << q << " of " << c;
        EXPECT_EQ(out.back().position, glm::vec3(1.0f, 2.0f, 3.0f));
      }
    }
}

TEST(LevelOfDetail, PairsAddUpAndEndsKeepOneHalf) {
  const std::vector<scene_light> lights{light(0x10, 0x98, 0x20), light(0x10, 0x38, 0xB0)};
  const std::vector<scene_light> seventy = split_for_lod(lights, 0.7);
  ASSERT_EQ(seventy.size(), 4u);
  for (std::size_t l = 0; l < 2; ++l)
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(seventy[2 * l].colour[c] + seventy[2 * l + 1].colour[c], lights[l].colour[c]);
      EXPECT_LE(std::fabs(seventy[2 * l].colour[c] - 0.7 * lights[l].colour[c]), 0.5);
    }
  const std::vector<scene_light> all = split_for_lod(lights, 1.0), none = split_for_lod(lights, 0.0);
  ASSERT_EQ(all.size(), 2u);
  ASSERT_EQ(none.size(), 2u);
  for (std::size_t l = 0; l < 2; ++l) {
    EXPECT_FALSE(all[l].gouraud);
    EXPECT_EQ(all[l].colour, lights[l].colour);
    EXPECT_TRUE(none[l].gouraud);
    EXPECT_EQ(none[l].colour, lights[l].colour);
  }
  EXPECT_TRUE(split_for_lod({light(0, 0, 0)}, 0.5).empty());
  EXPECT_EQ(light_method(method::four_pass, seventy[0]), method::four_pass);
  EXPECT_EQ(light_method(method::four_pass, seventy[1]), method::gouraud);
}

TEST(LevelOfDetail, ShareOutsideTheUnitIntervalIsAnError) {
  for (double bad : {-0.1, 1.5, std::nan("")})
    EXPECT_THROW((void)split_for_lod({light(1, 2, 3)}, bad), std::invalid_argument);
}

// The far level of detail's 4-bit map from the embedded 8-bit one: 16 unit entries, and each texel's
// entry is one nearest (largest dot product, brute force) to its 8-bit normal; widening keeps the
// indices; other widths are errors.
// The distance ramp at points whose share is an exact binary fraction, its ends, and bad ranges; the
// camera distance of a box seen from a 3-4-5 offset.
TEST(LevelOfDetail, ShareFallsLinearlyFromNearToFar) {
  EXPECT_EQ(lod_share_at(1.0, 2.0, 4.0), 1.0);
  EXPECT_EQ(lod_share_at(2.0, 2.0, 4.0), 1.0);
  EXPECT_EQ(lod_share_at(3.0, 2.0, 4.0), 0.5);
  EXPECT_EQ(lod_share_at(3.5, 2.0, 4.0), 0.25);
  EXPECT_EQ(lod_share_at(4.0, 2.0, 4.0), 0.0);
  EXPECT_EQ(lod_share_at(9.0, 2.0, 4.0), 0.0);
  EXPECT_THROW(lod_share_at(1.0, 4.0, 4.0), std::invalid_argument);
  EXPECT_THROW(lod_share_at(1.0, -1.0, 4.0), std::invalid_argument);
  scene s;
  s.model.vertices.resize(2);
  s.model.vertices[0].position = {-1.0f, 1.0f, -2.0f};
  s.model.vertices[1].position = {3.0f, 3.0f, 2.0f};  // centre (1, 2, 0)
  s.view.eye = {1.0f, 5.0f, 4.0f};
  EXPECT_EQ(camera_distance(s), 5.0);
  EXPECT_THROW(camera_distance(scene{}), std::invalid_argument);
}

TEST(NormalMapBits, FourBitsAreTheNearestOf16EntriesToTheEightBitNormals) {
  const normal_map eight = procedural_normal_map(64);
  ASSERT_EQ(eight.bits, 8);
  const normal_map four = with_index_bits(eight, 4);
  EXPECT_EQ(four.bits, 4);
  ASSERT_EQ(four.palette.size(), 16u);
  ASSERT_EQ(four.index.size(), eight.index.size());
  for (const glm::vec3& n : four.palette) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  std::vector<int> used(16);
  for (std::size_t i = 0; i < four.index.size(); ++i) {
    ASSERT_LT(four.index[i], 16);
    ++used[four.index[i]];
    const glm::vec3 n = eight.palette[eight.index[i]];
    float best = -2.0f;
    for (const glm::vec3& c : four.palette) best = std::max(best, glm::dot(n, c));
    ASSERT_GE(glm::dot(n, four.palette[four.index[i]]), best - 1e-6f) << "texel " << i;
  }
  for (int k = 0; k < 16; ++k) EXPECT_GT(used[static_cast<std::size_t>(k)], 0) << "entry " << k << " unused";
  const normal_map wide = with_index_bits(four, 8);
  EXPECT_EQ(wide.bits, 8);
  EXPECT_EQ(wide.index, four.index);
  EXPECT_EQ(with_index_bits(eight, 8).index, eight.index);
  EXPECT_THROW(with_index_bits(eight, 16), std::invalid_argument);
  EXPECT_THROW(with_index_bits(eight, 0), std::invalid_argument);
  // 24 bits: the unquantised normals quantise kept, read per texel (texel_normal); not from the 4-bit
  // map, nor from a map without them.
  ASSERT_EQ(eight.unquantised.size(), eight.index.size());
  const normal_map full = with_index_bits(eight, 24);
  EXPECT_EQ(full.bits, 24);
  EXPECT_EQ(full.index, eight.index);
  EXPECT_EQ(four.unquantised, eight.unquantised);
  for (std::size_t i = 0; i < full.index.size(); i += 97) {
    EXPECT_EQ(texel_normal(full, 0, i), eight.unquantised[i]);
    EXPECT_EQ(texel_normal(eight, 0, i), eight.palette[eight.index[i]]);
  }
  EXPECT_THROW(with_index_bits(four, 24), std::invalid_argument);
  normal_map bare = eight;
  bare.unquantised.clear();
  EXPECT_THROW(with_index_bits(bare, 24), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
