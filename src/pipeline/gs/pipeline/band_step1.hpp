// pipeline/band_step1.hpp — band_renderer's step 1 (included at the end of band_renderer.hpp): the Z
// buffer and the LAB's ambient colour, then the runs of the later passes; see depth_and_ambient's comment.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "gs_arith/depth_test.hpp"
#include "gs_arith/span_raster.hpp"
#include "gs_simd/pixel_span.hpp"
#include "gs_simd/span_draw.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/bit_runs.hpp"
#include "pipeline/scratch.hpp"

namespace gsdot3::pipeline::detail {

template <class FB>
void band_renderer::depth_and_ambient(const FB& lab, gs::rgba8 ambient) {
  constexpr gs::gs_registers regs = passes::step1_ambient.registers();
  const gs::fragment_colour cf = gs::fragment_colour::flat(ambient);
  constexpr bool rows = std::is_same_v<FB, row_view>;
  const bool lanes = rows && vectorised();
  const auto width = static_cast<std::size_t>(band_.x1 - band_.x0);
  scratch<std::uint32_t> no_texels(lanes ? width : 0);
  if (lanes) no_texels->assign(width, 0);
  // A triangle's depth in lanes (simd::depth_rows) where its plane fits them over its pixels: its rows
  // in `spans`, their pass bits in `pass`; then `passing` calls fn(x0, y, x1) for each run of passing pixels.
  scratch<run> spans;
  scratch<std::uint64_t> pass;
  auto depth_in_lanes = [&](const prepared_triangle& tri, const gs::zbuf_reg& zbuf) {
    const scissor r = covered_rectangle(tri.setup);
    if (!lanes || !simd::depth_row_applies(tri.z, r.x0, r.y0, r.x1, r.y1)) return false;
    spans->clear();
    std::size_t words = 0;
    gs::rasterise_spans(tri.setup, band_, [&](int y, int x0, int x1) {
      spans->push_back({x0, y, x1 - x0});
      words += static_cast<std::size_t>(x1 - x0 + 63) / 64;
    });
    pass->resize(words);
    simd::depth_rows(passes::depth_gequal, zbuf, tri.z, z_view::kept_bits, spans->data(), spans->size(), z_.rows.words,
                     static_cast<std::size_t>(z_.rows.width), pass->data());
    return true;
  };
  auto passing = [&](auto&& fn) {
    const std::uint64_t* bits = pass->data();
    for (const run& r : *spans) {
      for_each_bit_run(bits, static_cast<std::size_t>(r.n), [&](std::size_t a, std::size_t b) {
        fn(r.x0 + static_cast<int>(a), r.y, r.x0 + static_cast<int>(b));
      });
      bits += static_cast<std::size_t>(r.n + 63) / 64;
    }
  };
  for (std::size_t t = 0; t < ps_.triangles.size(); ++t) {
    const prepared_triangle& tri = ps_.triangles[t];
    if (depth_in_lanes(tri, passes::z_written)) {
      passing([&](int x0, int y, int x1) {
        const auto row = visible_.begin() + static_cast<std::ptrdiff_t>(index(0, y));
        std::fill(row + x0, row + x1, static_cast<std::int32_t>(t));
        if constexpr (rows)
          simd::span_row(batch_registers<passes::step1_ambient>, o_.model, cf, no_texels->data(), &lab(x0, y), x0, y,
                         static_cast<std::size_t>(x1 - x0));
        ops_ += static_cast<std::size_t>(x1 - x0);
      });
      continue;
    }
    gs::rasterise_spans(tri.setup, band_, [&](int y, int x0, int x1) {
      int from = x0;  // the SIMD path's passing pixels [from, x) not yet drawn
      auto ambient_run = [&](int end) {
        if constexpr (rows)
          if (end > from)
            simd::span_row(batch_registers<passes::step1_ambient>, o_.model, cf, no_texels->data(), &lab(from, y), from,
                           y, static_cast<std::size_t>(end - from));
      };
      gs::plane_walk z;
      z.start(tri.z, x0, y);
      for (int x = x0; x < x1; ++x, z.step(tri.z)) {
        const gs::depth_result d = gs::depth_test(passes::depth_gequal, passes::z_written,
                                                  static_cast<std::uint32_t>(z.at(tri.z)), z_.read(x, y));
        if (!d.pass) {
          if (lanes) ambient_run(x);
          from = x + 1;
          continue;
        }
        if (d.write_z) z_.write(x, y, d.z);
        visible_[index(x, y)] = static_cast<std::int32_t>(t);
        if (!lanes) lab(x, y) = gs_pixel(regs, gs::rgba8{}, cf, lab(x, y), x, y, o_.model);
        ++ops_;
      }
      if (lanes) ambient_run(x1);
    });
  }
  if (o_.path != raster_path::cached) return;
  // The runs: a row's pixels that pass the later passes' depth test, adjacent ones merged.
  runs_.clear();
  tri_runs_.assign(1, 0);
  frags_built_ = false;
  for (std::size_t t = 0; t < ps_.triangles.size(); ++t, tri_runs_.push_back(runs_.size())) {
    const prepared_triangle& tri = ps_.triangles[t];
    if (depth_in_lanes(tri, passes::z_masked)) {
      passing([&](int x0, int y, int x1) { runs_.push_back({x0, y, x1 - x0}); });
      continue;
    }
    gs::rasterise_spans(tri.setup, band_, [&](int y, int x0, int x1) {
      gs::plane_walk z;
      z.start(tri.z, x0, y);
      int from = x0;
      for (int x = x0; x < x1; ++x, z.step(tri.z)) {
        if (passes_later_depth_test(static_cast<std::uint32_t>(z.at(tri.z)), x, y)) continue;
        if (x > from) runs_.push_back({from, y, x - from});
        from = x + 1;
      }
      if (x1 > from) runs_.push_back({from, y, x1 - from});
    });
  }
}

}  // namespace gsdot3::pipeline::detail
