// tests/pipeline/normal_encoding_psnr_test.cpp — normal_encoding_psnr's as_2009 (seed 002 as the 2009
// article measured it) on the flat quad of test_scenes.hpp with its vertex normals bent about y: the
// interpolated normal's length in closed form, xyz's error by its formula written out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pipeline/scheme_normal_encoding.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

// The quad's left vertices (0, 2: x = 8) get n_L = (−sin h, −cos h·sin δ, cos h·cos δ), its right ones
// (1, 3: x = 56) n_R = (sin h, −cos h·sin δ, cos h·cos δ): (∓sin h, 0, cos h) turned by δ = 25° about x
// (off the pole (0, 0, 1), where CryEngine 3's normalize(xy) is NaN), h = β/2. The view (eye (0, 0, 3)
// at the origin) is the identity rotation.
test::flat_quad bent_quad(double beta) {
  auto q = test::make_flat_quad({0, 0, 1}, {0, 0, 1});
  const double h = beta / 2, d = 25 * std::numbers::pi / 180;
  const glm::vec3 left(glm::dvec3(-std::sin(h), -std::cos(h) * std::sin(d), std::cos(h) * std::cos(d)));
  const glm::vec3 right(glm::dvec3(std::sin(h), -std::cos(h) * std::sin(d), std::cos(h) * std::cos(d)));
  for (int k = 0; k < 4; ++k) {
    vertex v;
    v.normal = k == 0 || k == 2 ? left : right;
    v.tangent = glm::normalize(glm::cross(glm::vec3(0, 1, 0), v.normal));
    v.bitangent = glm::cross(v.normal, v.tangent);
    q.s.model.vertices.push_back(v);
  }
  return q;
}

std::vector<psnr_row> rows_of(const test::flat_quad& q) {
  const frame g = render(q.s, q.ps, method::four_pass, {});
  return normal_encoding_psnr(q.s, q.ps, g.visible_triangle, 8);
}
const psnr_row& row(const std::vector<psnr_row>& rows, const char* name) {
  for (const auto& r : rows)
    if (r.method == name) return r;
  throw std::runtime_error(name);
}

TEST(NormalEncodingPsnr, As2009OnABentQuadByHand) {
  const double beta = 60 * std::numbers::pi / 180;
  const auto q = bent_quad(beta);
  const auto rows = rows_of(q);
  // Pixel centres at integer x = 8..55 (t = (x − 8)/48 across), 32 rows: g = (1 − t)·n_L + t·n_R, the
  // same down a column whatever the triangle, |g| = sqrt((2t − 1)²·sin² h + cos² h).
  const glm::dvec3 nl(q.s.model.vertices[0].normal), nr(q.s.model.vertices[1].normal);
  double length = 0, given = 0, unit = 0;
  auto xyz = [](double c) { return 2 * std::floor((c / 2 + 0.5) * 255 + 0.5) / 255 - 1; };  // 3×8 round trip
  for (int x = 8; x < 56; ++x) {
    const double t = (x - 8) / 48.0;
    const glm::dvec3 g = (1 - t) * nl + t * nr, u = glm::normalize(g);
    length += std::hypot((2 * t - 1) * std::sin(beta / 2), std::cos(beta / 2));
    for (int c = 0; c < 3; ++c) {
      given += std::pow(xyz(g[c]) - g[c], 2);
      unit += std::pow(xyz(g[c]) - u[c], 2);
    }
  }
  const auto& r = row(rows, "xyz");
  ASSERT_EQ(r.pixels, 48u * 32u);
  EXPECT_NEAR(r.as_2009.mean_length, length / 48, 1e-6);
  EXPECT_LT(r.as_2009.mean_length, 1 - 1e-3);
  EXPECT_NEAR(r.as_2009.vs_given.mse, given / (3 * 48), 1e-9);
  EXPECT_NEAR(r.as_2009.vs_unit.mse, unit / (3 * 48), 1e-9);
  // The three methods that are one mapping for unit input part once |g| < 1.
  const double sph = row(rows, "spheremap").as_2009.vs_given.psnr, lam = row(rows, "lambert").as_2009.vs_given.psnr,
               cry = row(rows, "cryengine3").as_2009.vs_given.psnr;
  EXPECT_GT(std::fabs(sph - lam), 0.05);
  EXPECT_GT(std::fabs(sph - cry), 0.05);
  EXPECT_GT(std::fabs(lam - cry), 0.05);
}

TEST(NormalEncodingPsnr, As2009OnAFlatQuadIsTheNormalisedMeasure) {
  // β = 0: every g is the unit (0, 0, 1), so the 2009 encoders see unit input and the three agree.
  const auto rows = rows_of(bent_quad(0));
  EXPECT_NEAR(row(rows, "xyz").as_2009.mean_length, 1, 1e-7);
  const auto &sph = row(rows, "spheremap").as_2009, &lam = row(rows, "lambert").as_2009,
             &cry = row(rows, "cryengine3").as_2009;
  EXPECT_NEAR(sph.vs_given.mse, lam.vs_given.mse, 1e-15);
  EXPECT_NEAR(sph.vs_given.mse, cry.vs_given.mse, 1e-15);
  EXPECT_NEAR(sph.vs_given.mse, sph.vs_unit.mse, 1e-12);
}

}  // namespace
}  // namespace gsdot3::pipeline
