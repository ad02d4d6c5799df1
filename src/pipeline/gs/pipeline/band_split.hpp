// pipeline/band_split.hpp — where render.cpp cuts the frame into its threads' horizontal bands (internal). A band
// draws its rows of every pass, so rows are split by work, not by count: a row's work is counted as its pixels
// (the clears, the sprites and the display touch each of them a fixed number of times) plus `per_covered` times
// the pixels the mesh's triangles cover in it, overdraw included (every triangle pass walks them). The split only
// moves work between threads (Intel Xeon, 2 threads, 2026-12-07: the value path's four-pass frame 2.88 -> 2.81 ms
// with per_covered 4, 2.79 with 2 and 8; the memory path's 6.33 -> 6.57 ms, so it splits by rows, per_covered 0);
// every band draws its rows the same way wherever the cuts fall (pipeline_unit's scene tests compare frames drawn
// at 2 to 5 threads with one thread's reference-path frame; pipeline_memory_path compares its frames at 1 to 4
// threads with the value path's).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gs_arith/span_raster.hpp"
#include "pipeline/prepare.hpp"

namespace gsdot3::pipeline::detail {

// The first row of each of `bands` bands and, last, the frame's height: increasing, each band at least one
// row when the frame has as many rows as bands; each cut a multiple of `align` rows where that leaves every
// band a row (the memory path's: 32, a PSMCT32 page's height, so that its clears and channel-fetch sprites
// find whole pages in a band).
inline std::vector<int> band_rows(const prepared_scene& ps, int bands, int align, std::int64_t per_covered = 4) {
  std::vector<std::int64_t> work(static_cast<std::size_t>(ps.height), ps.width);
  for (const prepared_triangle& t : ps.triangles)
    gs::rasterise_spans(t.setup, {0, 0, ps.width, ps.height},
                        [&](int y, int x0, int x1) { work[static_cast<std::size_t>(y)] += per_covered * (x1 - x0); });
  std::int64_t total = 0;
  for (const std::int64_t w : work) total += w;
  std::vector<int> first(static_cast<std::size_t>(bands) + 1, ps.height);
  first[0] = 0;
  std::int64_t done = 0;
  int y = 0;
  for (int b = 1; b < bands; ++b) {
    while (y < ps.height && (done + work[static_cast<std::size_t>(y)]) * bands <= total * b)
      done += work[static_cast<std::size_t>(y++)];
    const int least = first[static_cast<std::size_t>(b) - 1] + 1, most = ps.height - (bands - b);
    const int aligned = (y + align / 2) / align * align;
    first[static_cast<std::size_t>(b)] = least > most                          ? ps.height
                                         : aligned >= least && aligned <= most ? aligned
                                                                               : std::clamp(y, least, most);
  }
  return first;
}

}  // namespace gsdot3::pipeline::detail
