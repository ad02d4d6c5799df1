// Seed 002's quality measure (seed_psnr.hpp): hand-worked MSE/PSNR of known differences, the seed's
// own published MSE/PSNR pairs, and the xyz baseline against uniform-quantisation theory.
#include <gtest/gtest.h>

#include <cmath>

#include "normal_encoding/methods.hpp"
#include "normal_encoding/sampling.hpp"
#include "normal_encoding/seed_psnr.hpp"

namespace ne = gsdot3::normal_encoding;

TEST(SeedPsnr, KnownDifferencesClampedAndNonFinite) {
  ne::seed_error_sum s;
  s.add({0, 0, 0}, {0.1, -0.2, 0.3});  // squares 0.01 + 0.04 + 0.09
  s.add({1, -1, 0}, {0.5, 1, -0.4});   // |−2| clamps to 1: 0.25 + 1 + 0.16
  s.add({0, 0, 1}, {NAN, 0, 0});       // full scale: 3
  const ne::seed_error e = s.done();
  EXPECT_EQ(e.samples, 3u);
  EXPECT_EQ(e.nonfinite, 1u);
  EXPECT_NEAR(e.mse, (0.14 + 1.41 + 3) / 9, 1e-15);
  EXPECT_NEAR(e.psnr, 10 * std::log10(9 / 4.55), 1e-12);
}

TEST(SeedPsnr, EightBitImageRoundsEachDifference) {
  // 0.1·255 = 25.5 rounds up to 26; 0.001·255 = 0.255 rounds to 0; 0.5·255 = 127.5 to 128.
  ne::seed_error_sum s(8);
  s.add({0, 0, 0}, {0.1, 0.001, 0.5});
  const double a = 26.0 / 255, c = 128.0 / 255;
  EXPECT_NEAR(s.done().mse, (a * a + c * c) / 3, 1e-15);
}

TEST(SeedPsnr, PublishedPairsFitPeakOne) {
  // Seed 002 prints MSE 0.0000054 with 52.661 dB (xyz) and 0.0312331 with 15.054 dB (#1): PSNR is
  // −10·log10(MSE) with peak 1 (to the MSE's printed digits).
  EXPECT_NEAR(-10 * std::log10(0.0312331), 15.054, 0.001);
  EXPECT_NEAR(-10 * std::log10(0.0000054), 52.661, 0.02);  // 5.4e-6 is rounded to 2 digits
}

TEST(SeedPsnr, XyzIsUniformQuantisationNoise) {
  // xyz stores each component on a grid of step 2/255, so over area-uniform unit directions each
  // channel's error is (nearly) uniform on [−1/255, 1/255]: E[e²] = (1/255)²/3, 52.90 dB. An 8-bit
  // difference image keeps 0 below 0.5/255 and 1/255 above: E = (1/255)²/2, 51.14 dB.
  const auto& m = ne::method_named("xyz");
  ne::seed_error_sum exact, image(8);
  constexpr std::uint64_t n = 65536;
  for (std::uint64_t k = 0; k < n; ++k) {
    const ne::vec3 v = ne::fibonacci_point(k, n);
    const ne::vec3 d = m.decode(m.encode(v, 8), 8);
    exact.add(v, d);
    image.add(v, d);
  }
  EXPECT_NEAR(exact.done().psnr, 10 * std::log10(3.0 * 255 * 255), 0.05);
  EXPECT_NEAR(image.done().psnr, 10 * std::log10(2.0 * 255 * 255), 0.1);
}
