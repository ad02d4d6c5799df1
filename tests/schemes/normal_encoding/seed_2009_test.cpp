// Seed 002 as the 2009 article measured it (seed_2009.hpp), against independent references: the
// length of an interpolated normal by trigonometry, the xyz round trip of a short vector by hand, the
// 2009 encoders of a short vector rewritten in terms of its length and direction, and the faceted
// sphere's pixels ray-cast into its planes with a depth test (not rasterised with back-face culling).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "normal_encoding/methods.hpp"
#include "normal_encoding/seed_2009.hpp"

namespace ne = gsdot3::normal_encoding;

namespace {
constexpr double pi = std::numbers::pi;
std::uint32_t unorm8(double v) { return static_cast<std::uint32_t>(std::floor(v * 255 + 0.5)); }
}  // namespace

TEST(Seed2009, MidpointOfTwoUnitNormalsIsCosOfHalfTheirAngle) {
  // Two unit normals 2α apart: their average has length cos α (the chord's midpoint).
  for (double alpha : {5.0, 11.25, 22.5, 40.0}) {
    const double a = alpha * pi / 180;
    const ne::vec3 n0{std::sin(a), 0, std::cos(a)}, n1{-std::sin(a), 0, std::cos(a)};
    EXPECT_NEAR(ne::length(ne::interpolate(n0, n1, {0, 0, 1}, 0.5, 0.5, 0)), std::cos(a), 1e-15) << alpha;
  }
  // The centroid of the octant's three axes: (1, 1, 1)/3, length 1/sqrt(3).
  EXPECT_NEAR(ne::length(ne::interpolate({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1 / 3.0, 1 / 3.0, 1 / 3.0)),
              1 / std::sqrt(3.0), 1e-15);
}

TEST(Seed2009, XyzOfAShortVectorByHand) {
  // v = (0.6, 0, 0): xyz stores v/2 + 1/2 = (0.8, 0.5, 0.5) as floor(255·c + 1/2) = (204, 128, 128) and
  // decodes 2q/255 − 1 = (0.6, 1/255, 1/255). Against v: (0, 1/255, 1/255); against normalize(v) =
  // (1, 0, 0): (0.4, 1/255, 1/255).
  ne::seed_2009_sum s;
  s.add(ne::method_named("xyz"), {0.6, 0, 0}, 8);
  const auto e = s.done();
  const double q = 1.0 / 255;
  EXPECT_NEAR(e.vs_given.mse, 2 * q * q / 3, 1e-15);
  EXPECT_NEAR(e.vs_unit.mse, (0.16 + 2 * q * q) / 3, 1e-15);
  EXPECT_DOUBLE_EQ(e.mean_length, 0.6);
}

TEST(Seed2009, EquivalentEncodersPartOnlyForShortVectors) {
  // v = ℓ·u, u unit. Written in ℓ and u (the seed's listings expanded by hand):
  //   #4 sphere map: a = ℓ·u.xy / (2·sqrt(ℓ² + 2ℓ·u.z + 1))
  //   #6 Lambert:    a = ℓ·u.xy / sqrt(8 + 8ℓ·u.z)
  //   #5 CryEngine 3: a = u.xy/|u.xy| · sqrt((1 − ℓ·u.z)/2) / 2
  // stored as floor(255·(a + 1/2) + 1/2). For ℓ = 1 all three are u.xy/sqrt(8(1 + u.z)).
  const double t = 100 * pi / 180, p = 70 * pi / 180;  // a normal 10° past the rim, as on the seed's spheres
  const ne::vec3 u{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
  const double r = std::hypot(u.x, u.y);
  for (double len : {1.0, std::cos(11.25 * pi / 180), std::cos(22.5 * pi / 180)}) {
    const ne::vec3 v = len * u;
    const double s4 = len / (2 * std::sqrt(len * len + 2 * len * u.z + 1)), s6 = len / std::sqrt(8 + 8 * len * u.z);
    const double s5 = std::sqrt((1 - len * u.z) / 2) / 2 / r;
    const std::array<std::uint32_t, 2> c4{unorm8(s4 * u.x + 0.5), unorm8(s4 * u.y + 0.5)},
        c6{unorm8(s6 * u.x + 0.5), unorm8(s6 * u.y + 0.5)}, c5{unorm8(s5 * u.x + 0.5), unorm8(s5 * u.y + 0.5)};
    const auto q4 = ne::method_named("spheremap").encode(v, 8), q6 = ne::method_named("lambert").encode(v, 8),
               q5 = ne::method_named("cryengine3").encode(v, 8);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(q4.c[static_cast<std::size_t>(k)], c4[static_cast<std::size_t>(k)]) << len;
      EXPECT_EQ(q6.c[static_cast<std::size_t>(k)], c6[static_cast<std::size_t>(k)]) << len;
      EXPECT_EQ(q5.c[static_cast<std::size_t>(k)], c5[static_cast<std::size_t>(k)]) << len;
    }
    if (len == 1.0) {
      EXPECT_TRUE(q4 == q6 && q6 == q5);
    } else {  // the three codes part: #5 keeps the direction's z, #4 and #6 shrink differently
      EXPECT_FALSE(q4 == q6) << len;
      EXPECT_FALSE(q6 == q5) << len;
      EXPECT_FALSE(q4 == q5) << len;
    }
  }
}

namespace {
// The faceted sphere by ray casting: each pixel centre's vertical line met with every facet's plane,
// kept if inside the facet (3D barycentric signs), the nearest to the viewer (largest z) wins. Its
// vertex normals being its positions, the interpolated normal there is the hit point itself.
std::vector<ne::vec3> ray_cast_sphere(int rings, int segments, int size) {
  auto vtx = [&](int i, int j) {
    const double th = pi * i / rings, ph = 2 * pi * j / segments;
    return ne::vec3{std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)};
  };
  std::vector<std::array<ne::vec3, 3>> tris;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      tris.push_back({vtx(i, j), vtx(i, j + 1), vtx(i + 1, j + 1)});
      tris.push_back({vtx(i, j), vtx(i + 1, j + 1), vtx(i + 1, j)});
    }
  std::vector<ne::vec3> out;
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      const double x = -1 + (2.0 * px + 1) / size, y = -1 + (2.0 * py + 1) / size;
      bool hit = false;
      ne::vec3 best{};
      for (const auto& [a, b, c] : tris) {
        const ne::vec3 n = ne::cross(b - a, c - a);
        if (ne::length(n) < 1e-9 || n.z == 0) continue;  // a pole's degenerate triangle, or edge-on
        const double z = a.z - (n.x * (x - a.x) + n.y * (y - a.y)) / n.z;
        const ne::vec3 q{x, y, z};
        const double e = 1e-12 * ne::dot(n, n);
        if (ne::dot(ne::cross(b - a, q - a), n) < -e || ne::dot(ne::cross(c - b, q - b), n) < -e ||
            ne::dot(ne::cross(a - c, q - c), n) < -e)
          continue;
        if (!hit || z > best.z) best = q;
        hit = true;
      }
      if (hit) out.push_back(best);
    }
  return out;
}
}  // namespace

TEST(Seed2009, FacetedSphereIsTheRayCastPolyhedron) {
  for (auto [rings, segments, size] : {std::array{8, 16, 40}, std::array{5, 7, 33}}) {
    const auto ours = ne::faceted_sphere_normals(rings, segments, size), ref = ray_cast_sphere(rings, segments, size);
    ASSERT_EQ(ours.size(), ref.size()) << rings << "x" << segments;
    double shortest = 1;
    for (std::size_t k = 0; k < ref.size(); ++k) {
      EXPECT_NEAR(ours[k].x, ref[k].x, 1e-12) << k;
      EXPECT_NEAR(ours[k].y, ref[k].y, 1e-12) << k;
      EXPECT_NEAR(ours[k].z, ref[k].z, 1e-12) << k;
      shortest = std::min(shortest, ne::length(ours[k]));
    }
    // Shorter than unit inside the faces (the seed's unnormalised input), never longer.
    EXPECT_LT(shortest, std::cos(pi / segments));
    for (const auto& v : ours) EXPECT_LE(ne::length(v), 1 + 1e-15);
  }
}
