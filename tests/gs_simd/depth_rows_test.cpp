// depth_rows (gs_simd/span_draw.hpp) against the scalar reference on every SIMD target this CPU supports
// (rapidcheck): a random depth plane (make_plane's fixed-point form from three random vertices with
// 24-bit depths, as the renderer's, or make_exact_plane's, lifted or not), 1 to 6 random rows of a
// 200×120 Z buffer (any x0, y and length, overlapping or not, in any order), stored words near the
// plane's depth or random, TEST's ZTE/ZTST, ZBUF's PSM and ZMSK, and a random keep mask. Row by row,
// every pixel's pass bit must be gs::depth_test(test, zbuf, plane::at(x, y), its word).pass, the word
// (word & keep) | (z & ~keep) exactly where the test writes Z, every other word of the buffer unchanged,
// the bits past each row's n zero and the count the bits' popcount.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "gs_arith/depth_test.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_simd/span_draw.hpp"
#include "lanes.hpp"

namespace gsdot3::simd::test {
namespace {

gs::plane random_plane() {
  std::array<gs::xy124, 3> v{};
  for (auto& p : v) p = {*rc::gen::inRange(0, 200 * 16), *rc::gen::inRange(0, 120 * 16)};
  const std::int64_t area =
      std::int64_t{v[1].x - v[0].x} * (v[2].y - v[0].y) - std::int64_t{v[2].x - v[0].x} * (v[1].y - v[0].y);
  RC_PRE(area != 0);
  std::array<std::int32_t, 3> z{};
  for (auto& d : z) d = *rc::gen::inRange(0, 1 << 24);
  const int lo = *rc::gen::inRange(0, 1 << 23), hi = *rc::gen::inRange(lo, 1 << 24);
  if (*rc::gen::inRange(0, 3) != 0) return gs::make_plane(v, z, lo, hi);
  gs::plane p = gs::make_exact_plane(v, z, lo, hi);
  p.lift_1_64 = *rc::gen::arbitrary<bool>();
  return p;
}

constexpr int width = 200, height = 120;  // the Z buffer, row-major

void rows_equal_scalar(const std::string& target) {
  const gs::plane p = random_plane();
  RC_PRE(depth_row_applies(p, 0, 0, width, height));
  std::vector<span_run> rows(static_cast<std::size_t>(*rc::gen::inRange(1, 7)));
  for (span_run& r : rows) {
    r.y = *rc::gen::inRange(0, height), r.x0 = *rc::gen::inRange(0, width);
    r.n = *rc::gen::inRange(1, width - r.x0 + 1);  // from 1 pixel to beyond three AVX-512 vectors
  }
  gs::test_reg test;
  test.ZTE = *rc::gen::arbitrary<bool>();
  test.ZTST = static_cast<gs::ztst>(*rc::gen::inRange(0, 4));
  gs::zbuf_reg zbuf;
  zbuf.PSM = *rc::gen::element(gs::zbuf_psm::PSMZ32, gs::zbuf_psm::PSMZ24, gs::zbuf_psm::PSMZ16, gs::zbuf_psm::PSMZ16S);
  zbuf.ZMSK = *rc::gen::arbitrary<bool>();
  const std::uint32_t keep = *rc::gen::element(0u, 0xFF000000u, *rc::gen::arbitrary<std::uint32_t>());
  std::vector<std::uint32_t> want(static_cast<std::size_t>(width * height));
  const std::uint32_t seed = *rc::gen::arbitrary<std::uint32_t>();
  for (std::size_t i = 0; i < want.size(); ++i) {
    // Stored depths near the plane's in half the pixels, so that both outcomes of the test occur.
    const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
    const std::uint32_t h = (static_cast<std::uint32_t>(i) + seed) * 2654435761u;
    want[i] = (h & 1) != 0 ? static_cast<std::uint32_t>(p.at(x, y) + static_cast<int>(h >> 26) - 32) : h;
  }
  std::vector<std::uint32_t> got = want;
  std::size_t words = 0;
  for (const span_run& r : rows) words += (static_cast<std::size_t>(r.n) + 63) / 64;
  std::vector<std::uint64_t> pass(words, ~std::uint64_t{0});
  const std::size_t passed = depth_rows(test, zbuf, p, keep, rows.data(), rows.size(), got.data(), width, pass.data());
  std::size_t expected_passed = 0, ones = 0;
  const std::uint64_t* bits = pass.data();
  for (const span_run& r : rows) {
    for (int k = 0; k < r.n; ++k) {
      std::uint32_t& w = want[static_cast<std::size_t>(r.y * width + r.x0 + k)];
      const gs::depth_result d = gs::depth_test(test, zbuf, static_cast<std::uint32_t>(p.at(r.x0 + k, r.y)), w);
      if (((bits[k / 64] >> (k % 64)) & 1) != (d.pass ? 1u : 0u))
        RC_FAIL("target " + target + ": pass bit of (" + std::to_string(r.x0 + k) + ", " + std::to_string(r.y) + ")");
      if (d.write_z) w = (w & keep) | (d.z & ~keep);
      expected_passed += d.pass ? 1 : 0;
    }
    bits += (static_cast<std::size_t>(r.n) + 63) / 64;
  }
  RC_ASSERT(got == want);
  for (const std::uint64_t w : pass) ones += static_cast<std::size_t>(std::popcount(w));
  RC_ASSERT(ones == expected_passed);  // no bit past a row's n
  RC_ASSERT(passed == expected_passed);
}

TEST(DepthRows, RowsEqualTheScalarDepthTestOnEveryTarget) {
  for_each_target([](const std::string& target) {
    const bool ok = rc::check("depth_rows on " + target, [&] { rows_equal_scalar(target); });
    EXPECT_TRUE(ok) << target;
  });
}

// A plane too steep for 32-bit lanes on a wide row is refused, and a flat one accepted.
TEST(DepthRows, PlanesBeyondTheLanesAreRefused) {
  gs::plane steep;
  steep.dx = std::int64_t{1} << 40, steep.hi = 0xFFFFFF;
  EXPECT_FALSE(depth_row_applies(steep, 0, 0, 512, 1));
  gs::plane flat;
  flat.base = std::int64_t{0x123456} << 16, flat.hi = 0xFFFFFF;
  EXPECT_TRUE(depth_row_applies(flat, 0, 0, 512, 1));
}

}  // namespace
}  // namespace gsdot3::simd::test
