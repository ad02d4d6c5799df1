// The transcription of the paper's encoders (Appendices 1, 2; section 3.5's light packing), checked
// on hand-computed cases.
#include <gtest/gtest.h>

#include "proofs/paper_code.hpp"

namespace paper = gsdot3::proofs::paper;

TEST(PaperCode, NearestRoundsHalvesAwayFromZero) {
  EXPECT_EQ(paper::nearest(2.5f), 3);
  EXPECT_EQ(paper::nearest(-2.5f), -3);
  EXPECT_EQ(paper::nearest(0.49f), 0);
  EXPECT_EQ(paper::nearest(-126.6f), -127);
}

TEST(PaperCode, PackNormalByHand) {
  // (0, 0): iZ = sqrt(16384) = 128; delta = −128; alpha = (384 − 128 + 1) / 3 = 85.
  const auto up = paper::pack_normal(0.0f, 0.0f);
  EXPECT_EQ(up.iZ, 128);
  EXPECT_EQ(up.B_pos, 128);
  EXPECT_EQ(up.alpha, 85);
  // (1, 0): iX = (int)127.9f = 127; iZ = (int)sqrt(16384 − 16129 = 255) = 15; delta = −142;
  // alpha = (384 − 142 + 1) / 3 = 81.
  const auto x = paper::pack_normal(1.0f, 0.0f);
  EXPECT_EQ(x.iX, 127);
  EXPECT_EQ(x.iZ, 15);
  EXPECT_EQ(x.alpha, 81);
  EXPECT_TRUE(x.assert_le && x.assert_gt);
  // (−0.6, −0.6): iX = iY = (int)(−76.74) = −76; iZ = (int)sqrt(16384 − 11552 = 4832) = 69;
  // delta = 76 + 76 − 69 = 83; alpha = (384 + 83 + 1) / 3 = 156; R_neg = G_neg = 76.
  const auto n = paper::pack_normal(-0.6f, -0.6f);
  EXPECT_EQ(n.iX, -76);
  EXPECT_EQ(n.iZ, 69);
  EXPECT_EQ(n.R_neg, 76);
  EXPECT_EQ(n.R_pos, 0);
  EXPECT_EQ(n.alpha, 156);
}

TEST(PaperCode, SphereMapTexelByHand) {
  // 2×2 map, texel (0, 0): s = t = 0.25, s2 = t2 = −0.5, Lz = 1 − 2·0.5 = 0, m = 2·sqrt(2) and
  // L = (−0.25·m, −0.25·m, 0) = (−0.7071, −0.7071, 0); 127·0.7071 = 89.8 -> 90, r = g = 218, b = 128.
  const auto t = paper::sphere_map_texel(0, 0, 2, 2);
  EXPECT_TRUE(t.inside);
  EXPECT_EQ(t.r, 218);
  EXPECT_EQ(t.g, 218);
  EXPECT_EQ(t.b, 128);
  // Corner texel of a 16×16 map: s2 = t2 = −15/16, ρ² = 1.7578 > 1, Lz < −1: the zero vector.
  const auto c = paper::sphere_map_texel(0, 0, 16, 16);
  EXPECT_FALSE(c.inside);
  EXPECT_EQ(paper::generate_sphere_map(16, 16)[0], 0x808080u);
  EXPECT_EQ(paper::generate_sphere_map(2, 2)[0], (128u << 16) | (218u << 8) | 218u);
}

TEST(PaperCode, LightPackingTruncatesTowardZero) {
  EXPECT_EQ(paper::pack_light_component(122.0f, 1.0f), 122);
  EXPECT_EQ(paper::pack_light_component(122.0f, -0.5f), -61);
  EXPECT_EQ(paper::pack_light_component(122.0f, 0.999f), 121);
  EXPECT_EQ(paper::pack_light_component(122.0f, -0.999f), -121);
}
