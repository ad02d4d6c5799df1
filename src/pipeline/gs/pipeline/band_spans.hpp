// pipeline/band_spans.hpp — band_renderer's passes in SIMD lanes (included at the end of
// band_renderer.hpp): the fills of a band, the memory path's sprite rows through the address tables, and a triangle
// pass's cached runs through the span engine (gs_simd/span_draw.hpp) where it applies (on the memory path through the
// buffers' address tables), else walked by gs::attribute_walker into span_batch.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "pipeline/band_renderer.hpp"

namespace gsdot3::pipeline::detail {

// draw() through span_batch: one batch per triangle (the cached fragments are in triangle order),
// the attributes stepped along each row (gs::attribute_walker, equal to colour_at and plane::at).
// Not inlined into draw<Pass> (whose scalar loop is compiled per register set): one copy per view,
// everything it calls inlined into it.
template <class FB>
[[gnu::noinline, gnu::flatten]] void band_renderer::draw_spans(const gs::gs_registers& regs, const texture_ref* tex,
                                                               const std::vector<tri_attr>& attr, const FB& fb,
                                                               triangle_range tris) {
  span_batch batch(regs, o_.model);
  auto add = [&](gs::attribute_walker& w, int x, int y) {
    const gs::attribute_walker::values a = w.at(x, y);
    const gs::rgba8 texel = tex != nullptr ? tex->sample(a.u, a.v) : gs::rgba8{};
    batch.add(fb(x, y), texel, a.cf, x, y);
    ++ops_;
  };
  if (o_.path == raster_path::cached) {
    auto runs_of = [&](std::uint32_t t) { return of(runs_, tri_runs_, {t, t + 1}); };
    if constexpr (!std::is_same_v<FB, row_view>) {
      // The memory path: the span engine through the buffer's and the texture's address tables where it
      // applies, else pixel by pixel.
      std::optional<nearest_memory_fetch> fetch;
      simd::nearest_texture lanes;  // no texture: none
      bool engine = o_.span_engine && fb.address != nullptr;
      if (tex != nullptr && engine) {
        if (nearest_memory_fetch::applies(*tex))
          lanes = fetch.emplace(*tex).lanes();
        else
          engine = false;
      }
      for (std::uint32_t t = tris.first; t < tris.end; ++t, batch.flush()) {
        if (engine && span_engine(regs, attr[t], lanes, runs_of(t), span_target_of(fb))) continue;
        gs::attribute_walker w(attr[t]);
        for (const run& r : runs_of(t))
          for (int k = 0; k < r.n; ++k) add(w, r.x0 + k, r.y);
      }
    } else {
      // The runs with texel(u16, v16) as the fetch, instantiated per kind of fetch (no test per
      // pixel); a run's words are adjacent. The span engine takes the triangles in its domain.
      auto runs = [&](auto&& texel, const simd::nearest_texture* lanes) {
        for (std::uint32_t t = tris.first; t < tris.end; ++t) {
          const std::span<const run> rs = runs_of(t);
          if (lanes != nullptr && span_engine(regs, attr[t], *lanes, rs, span_target_of(fb))) continue;
          gs::attribute_walker w(attr[t]);
          for (const run& r : rs) {
            batch.add_row(&fb(r.x0, r.y), r.x0, r.y, [&](auto&& put) {
              w.row(r.x0, r.y, r.n, [&](int, const gs::attribute_walker::values& a) { put(texel(a.u, a.v), a.cf); });
            });
            ops_ += static_cast<std::size_t>(r.n);
          }
          batch.flush();
        }
      };
      if (tex == nullptr) {
        const simd::nearest_texture none;
        runs([](std::int32_t, std::int32_t) { return 0u; }, o_.span_engine ? &none : nullptr);
      } else if (nearest_host_fetch::applies(*tex)) {
        const nearest_host_fetch fetch(*tex);
        const simd::nearest_texture lanes = fetch.lanes();
        const bool four = tex->width * tex->height >= 4;  // the span engine's fetch reads whole words
        runs([&](std::int32_t u, std::int32_t v) { return fetch.texel(u, v); },
             o_.span_engine && four ? &lanes : nullptr);
      } else {
        runs([&](std::int32_t u, std::int32_t v) { return tex->sample(u, v).to_u32(); }, nullptr);
      }
    }
    return;
  }
  for (std::size_t t = tris.first; t < tris.end; ++t) {
    gs::attribute_walker w(attr[t]);
    rasterise_triangle(ps_.triangles[t].setup, band_, [&](int x, int y) {
      if (passes_later_depth_test(ps_.triangles[t], x, y)) add(w, x, y);
    });
    batch.flush();
  }
}

// v into the band's pixels of fb, the bits of `keep` kept. A memory buffer's pages that lie wholly in
// the band (a 32-bit page is 2048 words in a row, FBP a whole page) are set in memory order.
template <class FB>
void band_renderer::fill_band(const FB& fb, std::uint32_t v, std::uint32_t keep) {
  auto merge = [&](std::uint32_t& w) { w = (w & keep) | (v & ~keep); };
  scissor pages{};  // the band's whole pages, in pixels (empty on the value path)
  if constexpr (std::is_same_v<FB, memory_view>) {
    if (fb.address != nullptr && fb.bp % 32 == 0)
      pages = {(band_.x0 + 63) / 64 * 64, (band_.y0 + 31) / 32 * 32, band_.x1 / 64 * 64, band_.y1 / 32 * 32};
    for (int py = pages.y0; py < pages.y1; py += 32)
      for (int px = pages.x0; px < pages.x1; px += 64) {
        std::uint32_t* page = fb.words + fb.page_of(px, py);
        for (std::size_t k = 0; k < 2048; ++k) merge(page[k]);
      }
  }
  for (int y = band_.y0; y < band_.y1; ++y) {
    const bool paged = y >= pages.y0 && y < pages.y1 && pages.x0 < pages.x1;
    if (std::is_same_v<FB, row_view> && keep == 0 && band_.x0 < band_.x1) {
      std::fill(&fb(band_.x0, y), &fb(band_.x0, y) + (band_.x1 - band_.x0), v);
      continue;
    }
    auto part = [&](int x0, int x1) {
      if constexpr (std::is_same_v<FB, memory_view>) {
        fb.row(y, x0, x1, [&](int, std::uint32_t& w) { merge(w); });
      } else {
        for (int x = x0; x < x1; ++x) merge(fb(x, y));
      }
    };
    if (paged) {
      part(band_.x0, pages.x0), part(pages.x1, band_.x1);
    } else {
      part(band_.x0, band_.x1);
    }
  }
}

// A sprite's rectangle r on the memory path, row by row through the span engine's sprite row: each row's
// words through the buffer's address tables (distinct within a row, read before any is written, as
// span_batch reads them), drawn and stored back.
template <class Texel>
void band_renderer::memory_rows(const gs::gs_registers& regs, const gs::fragment_colour& cf, scissor r, Texel&& texel,
                                const memory_view& fb) {
  const auto n = static_cast<std::size_t>(r.x1 - r.x0);
  scratch<std::uint32_t> store(3 * n);
  store->resize(3 * n);
  std::uint32_t *at = store->data(), *words = at + n, *texels = words + n;
  const std::uint32_t *column = fb.address->columns() + r.x0, mask = fb.address->mask();
  for (int y = r.y0; y < r.y1; ++y) {
    const std::uint32_t row = fb.address->rows()[y];
    for (std::size_t k = 0; k < n; ++k) at[k] = (row + column[k]) & mask, words[k] = fb.words[at[k]];
    for (int x = r.x0; x < r.x1; ++x) texels[x - r.x0] = texel(x, y).to_u32();
    simd::span_row(regs, o_.model, cf, texels, words, r.x0, y, n);
    for (std::size_t k = 0; k < n; ++k) fb.words[at[k]] = words[k];
  }
  ops_ += n * static_cast<std::size_t>(r.y1 - r.y0);
}

// A triangle's runs through the span engine (gs_simd/span_draw.hpp) when it is in its domain.
inline bool band_renderer::span_engine(const gs::gs_registers& regs, const tri_attr& a,
                                       const simd::nearest_texture& tex, std::span<const run> rs,
                                       const simd::span_target& fb) {
  if (rs.empty()) return true;
  int x0 = rs.front().x0, x1 = x0;
  for (const run& r : rs) x0 = std::min(x0, r.x0), x1 = std::max(x1, r.x0 + r.n);
  if (!simd::span_applies(a, x0, rs.front().y, x1, rs.back().y + 1)) return false;
  simd::span_triangle(regs, o_.model, a, tex, rs.data(), rs.size(), fb);
  for (const run& r : rs) ops_ += static_cast<std::size_t>(r.n);
  return true;
}
}  // namespace gsdot3::pipeline::detail
