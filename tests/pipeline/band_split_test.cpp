// pipeline_unit: detail::band_rows (band_split.hpp) on the default scene at sizes down to fewer rows than
// bands: the cuts start at 0, end at the height and increase; page-aligned where asked; and the work the
// header counts, recounted here pixel by pixel (rasterise_triangle, not spans), differs between two bands by at
// most two rows' work (the greedy cut's bound: one row each side).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

#include "gs_arith/rasteriser.hpp"
#include "pipeline/band_split.hpp"
#include "pipeline/default_scene.hpp"

namespace {

using namespace gsdot3::pipeline;

TEST(BandSplit, CutsIncreaseAlignAndBalanceTheCountedWork) {
  scene s = default_scene();
  for (const auto& [w, h] : {std::pair{512, 448}, std::pair{97, 61}, std::pair{33, 3}, std::pair{40, 1}}) {
    s.width = w, s.height = h;
    const prepared_scene ps = prepare(s);
    std::vector<std::int64_t> work(static_cast<std::size_t>(h), w);  // per_covered 4
    for (const prepared_triangle& t : ps.triangles)
      gs::rasterise_triangle(t.setup, {0, 0, w, h}, [&](int, int y) { work[static_cast<std::size_t>(y)] += 4; });
    std::int64_t widest = 0;
    for (const std::int64_t k : work) widest = std::max(widest, k);
    for (int bands = 1; bands <= 5; ++bands) {
      const std::vector<int> first = detail::band_rows(ps, bands, 1);
      ASSERT_EQ(first.size(), static_cast<std::size_t>(bands) + 1);
      EXPECT_EQ(first.front(), 0);
      EXPECT_EQ(first.back(), h);
      std::vector<std::int64_t> per_band;
      for (int b = 0; b < bands; ++b) {
        const int y0 = first[static_cast<std::size_t>(b)], y1 = first[static_cast<std::size_t>(b) + 1];
        if (h >= bands) { ASSERT_LT(y0, y1) << w << "x" << h << ", " << bands << " bands"; }
        ASSERT_LE(y0, y1);
        std::int64_t sum = 0;
        for (int y = y0; y < y1; ++y) sum += work[static_cast<std::size_t>(y)];
        per_band.push_back(sum);
      }
      if (h >= 4 * bands) {
        for (const std::int64_t a : per_band)
          for (const std::int64_t b : per_band) EXPECT_LE(std::abs(a - b), 2 * widest) << w << "x" << h;
      }
      // By rows on whole pages (the memory path's): 448 rows in two bands are cut at 224, in three at 160 and 288.
      if (h == 448 && bands > 1) {
        for (int b = 1; b < bands; ++b)
          EXPECT_EQ(detail::band_rows(ps, bands, 32, 0)[static_cast<std::size_t>(b)] % 32, 0);
      }
    }
    if (h == 448) {
      EXPECT_EQ(detail::band_rows(ps, 2, 32, 0), (std::vector<int>{0, 224, 448}));
      EXPECT_EQ(detail::band_rows(ps, 3, 32, 0), (std::vector<int>{0, 160, 288, 448}));
    }
  }
}

}  // namespace
