// Round trips on the axis directions and octant diagonals, with the expected codes and decoded
// vectors worked out by hand from the seed's formulas (comments), and the one-line errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "normal_encoding/methods.hpp"
#include "normal_encoding/octahedral.hpp"
#include "normal_encoding/spheremap.hpp"

namespace ne = gsdot3::normal_encoding;

namespace {
ne::code enc(std::string_view m, ne::vec3 n, int bits = 8) { return ne::method_named(m).encode(n, bits); }
ne::vec3 dec(std::string_view m, ne::code q, int bits = 8) { return ne::method_named(m).decode(q, bits); }
void expect_code(ne::code q, unsigned a, unsigned b, unsigned c = 0) {
  EXPECT_EQ(q.c[0], a);
  EXPECT_EQ(q.c[1], b);
  EXPECT_EQ(q.c[2], c);
}
const double r3 = 1 / std::sqrt(3.0);
}  // namespace

TEST(NormalEncoding, XyzAxesAndDiagonal) {
  // enc = n/2 + 1/2; q = floor(255·enc + 1/2): 1 -> 255, 0 -> floor(128) = 128, −1 -> 0;
  // 1/√3 -> floor(255·0.788675 + 0.5) = floor(201.61) = 201.
  expect_code(enc("xyz", {1, 0, 0}), 255, 128, 128);
  expect_code(enc("xyz", {0, 0, -1}), 128, 128, 0);
  expect_code(enc("xyz", {r3, r3, r3}), 201, 201, 201);
  expect_code(enc("xyz", {-r3, -r3, -r3}), 54, 54, 54);  // 255·0.211325 + 0.5 = 54.39
  const ne::vec3 d = dec("xyz", {{255, 128, 0}});
  EXPECT_DOUBLE_EQ(d.x, 1);
  EXPECT_NEAR(d.y, 1.0 / 255, 1e-15);  // 2·128/255 − 1 (cancellation: not to the ulp)
  EXPECT_DOUBLE_EQ(d.z, -1);
}

TEST(NormalEncoding, XyLosesTheSignAndHitsTheDiscCorner) {
  // (0, 0, −1): code (128, 128) decodes to (1/255, 1/255, sqrt(1 − 2/255²)) — nearly +z.
  expect_code(enc("xy", {0, 0, -1}), 128, 128);
  const ne::vec3 d = dec("xy", {{128, 128, 0}});
  EXPECT_DOUBLE_EQ(d.z, std::sqrt(1 - 2.0 / (255.0 * 255.0)));
  // (1, 0, 0) -> (255, 128): 1 + 1/255² > 1, sqrt of a negative.
  EXPECT_TRUE(std::isnan(dec("xy", enc("xy", {1, 0, 0})).z));
  // #2 keeps the sign.
  expect_code(enc("xy-sign", {0, 0, -1}), 128, 128, 1);
  EXPECT_LT(dec("xy-sign", {{128, 128, 1}}).z, 0);
}

TEST(NormalEncoding, SphericalAxes) {
  // enc.x = (atan2(y, x)/kPI + 1)/2: (1,0,0) -> 1/2 -> 128; (0,1,0) -> 3/4·(π/kPI) -> floor(191.75) = 191;
  // (−1,0,0) -> atan2(0, −1) = π -> (π/kPI + 1)/2 ≈ 1 − 1e-11 -> 255. enc.y = (z + 1)/2.
  expect_code(enc("spherical", {1, 0, 0}), 128, 128);
  expect_code(enc("spherical", {0, 1, 0}), 191, 128);
  expect_code(enc("spherical", {-1, 0, 0}), 255, 128);
  expect_code(enc("spherical", {0, 0, 1}), 128, 255);
  // code (255, 128): ang = (1, 1/255): n = (cos kPI·r, sin kPI·r, 1/255), r = sqrt(1 − 1/255²).
  const ne::vec3 d = dec("spherical", {{255, 128, 0}});
  EXPECT_NEAR(d.x, -std::sqrt(1 - 1.0 / (255.0 * 255.0)), 1e-15);
  EXPECT_NEAR(d.z, 1.0 / 255, 1e-15);
}

TEST(NormalEncoding, SphereMapLambertCryAxes) {
  // a = n.xy/sqrt(8(1 + z)): +z -> a = 0 -> code (128, 128); +x -> a.x = 1/sqrt 8 = 0.353553,
  // enc 0.853553 -> floor(218.16) = 218; (r3, r3, r3): 8(1 + r3) = 12.6188, a = 0.162529,
  // enc 0.662529 -> floor(169.445) = 169.
  for (auto m : {"spheremap", "lambert"}) {
    expect_code(enc(m, {0, 0, 1}), 128, 128);
    expect_code(enc(m, {1, 0, 0}), 218, 128);
    expect_code(enc(m, {r3, r3, r3}), 169, 169);
    EXPECT_TRUE(std::isnan(dec(m, enc(m, {0, 0, -1})).z) || std::isnan(dec(m, enc(m, {0, 0, -1})).x)) << m;
  }
  expect_code(enc("cryengine3", {1, 0, 0}), 218, 128);  // normalize((1,0))·sqrt(1/2)/2 + 1/2 = 0.853553
  expect_code(enc("cryengine3", {0, 0, 1}), 0, 0);      // normalize(0) = NaN, stored as 0
  // Lambert's decode of code (218, 128): a = (218/255 − 1/2, 1/510); n = (4a·sqrt(1 − 4|a|²), 1 − 8|a|²).
  const double ax = 218.0 / 255 - 0.5, ay = 128.0 / 255 - 0.5, r2 = ax * ax + ay * ay;
  const ne::vec3 d = dec("lambert", {{218, 128, 0}});
  EXPECT_NEAR(d.x, 4 * ax * std::sqrt(1 - 4 * r2), 1e-15);
  EXPECT_NEAR(d.z, 1 - 8 * r2, 1e-15);
}

TEST(NormalEncoding, StereographicAxes) {
  // X = x/(1 + z)/1.7777: +x -> 0.562525, enc 0.781263 -> floor(199.72) = 199; +z -> 128;
  // (0, 0, −1): 0/0 -> NaN -> 0.
  expect_code(enc("stereographic", {1, 0, 0}), 199, 128);
  expect_code(enc("stereographic", {0, 0, 1}), 128, 128);
  expect_code(enc("stereographic", {0, 0, -1}), 0, 0);
}

TEST(NormalEncoding, OctahedralAxesAndDiagonals) {
  // +z: (u, v) = 0 -> 128; +x: u = 1 -> 255; −z folds to (1, 1) -> (255, 255) which decodes exactly;
  // (r3, r3, r3): u = 1/3 -> floor(255·2/3 + 0.5) = 170; (r3, r3, −r3) folds to (2/3, 2/3) ->
  // floor(255·5/6 + 0.5) = 213.
  expect_code(enc("octahedral", {0, 0, 1}), 128, 128);
  expect_code(enc("octahedral", {1, 0, 0}), 255, 128);
  expect_code(enc("octahedral", {0, 0, -1}), 255, 255);
  expect_code(enc("octahedral", {r3, r3, r3}), 170, 170);
  expect_code(enc("octahedral", {r3, r3, -r3}), 213, 213);
  const ne::vec3 d = dec("octahedral", {{255, 255, 0}});
  EXPECT_DOUBLE_EQ(d.z, -1);
  // snorm: u = 1/3 -> round(42.33) = 42, stored + 128; −z -> (127, 127) -> 255, 255.
  expect_code(enc("octahedral-snorm", {r3, r3, r3}), 170, 170);
  expect_code(enc("octahedral-snorm", {0, 0, -1}), 255, 255);
  expect_code(enc("octahedral-snorm", {-1, 0, 0}), 1, 128);  // −127 + 128
  // snorm decode clamps −128 to −1.
  EXPECT_DOUBLE_EQ(ne::snorm_decode(-128, 8), -1);
  // Precise never does worse than nearest (the nearest is among its four candidates).
  for (ne::vec3 n : {ne::vec3{0.3, 0.5, -0.81}, ne::vec3{r3, r3, -r3}, ne::vec3{0.1, 0.9, 0.42}}) {
    n = ne::normalize(n);
    EXPECT_LE(ne::angle(dec("octahedral", enc("octahedral-precise", n)), n),
              ne::angle(dec("octahedral", enc("octahedral", n)), n) + 1e-15);
  }
}

TEST(NormalEncoding, ViewSpaceIsXyInTheViewFrame) {
  // View down −z: the frame is the identity; so #8 = #1 there. View along y: normalize(0) = NaN.
  for (ne::vec3 n : {ne::vec3{0.6, 0, 0.8}, ne::vec3{0, 0, 1}}) { EXPECT_EQ(enc("view-space", n), enc("xy", n)); }
}

TEST(NormalEncoding, BadParametersAreOneLineErrors) {
  for (int bits : {0, 3, 17, 32, -8}) {
    for (const auto& m : ne::methods()) {
      try {
        m.encode({0, 0, 1}, bits);
        ADD_FAILURE() << m.name << " accepted " << bits << " bits";
      } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos);
        EXPECT_NE(what.find(std::to_string(bits)), std::string::npos) << what;
      }
    }
  }
  EXPECT_THROW(ne::method_named("spherical-lut").encode({0, 0, 1}, 10), std::invalid_argument);
  EXPECT_THROW(ne::code_count(ne::method_named("spherical-lut"), 12), std::invalid_argument);
  EXPECT_THROW(ne::method_named("no-such-method"), std::invalid_argument);
}
