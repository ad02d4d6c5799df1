// pipeline/band_renderer.hpp — drawing GS passes over one horizontal band of the frame (internal
// to render.cpp): step 1 (Z and ambient), triangle passes with ZTST = GEQUAL, 2D sprite passes, and
// the per-triangle attributes (gs::gouraud_triangle colour planes, UV planes) a pass draws with.
// Every pixel goes through gs::pixel_pipeline with the pass's registers as a compile-time constant,
// and every triangle pixel through gs::depth_test with the pass's TEST_1 / ZBUF_1.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/attribute_walk.hpp"
#include "gs_arith/depth_test.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/perspective.hpp"
#include "gs_arith/span_raster.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/swizzle_tables.hpp"
#include "pipeline/frame_views.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/pass_attributes.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scratch.hpp"
#include "pipeline/method.hpp"
#include "pipeline/texture_stream.hpp"
#include "pipeline/span_batch.hpp"

namespace gsdot3::pipeline::detail {

// One band of the frame and its buffers (rows [band.y0, band.y1) of the frame-sized buffers).
class band_renderer {
 public:
  band_renderer(const prepared_scene& ps, const render_options& o, scissor band, const z_view& z,
                std::vector<std::int32_t>& visible)
      : ps_(ps), o_(o), band_(band), sprite_area_(drawn_area(ps, band)), z_(z), visible_(visible) {}

  // Step 1: the LAB's ambient colour and the Z buffer (ZTST = GEQUAL, Z written), after the frame
  // program's clears of both; then, on the cached path, the runs every later pass draws. Depth is
  // walked along each row (gs::plane_walk, equal to plane::at). On the SIMD path with the Z buffer in
  // rows, a row's depth test is done in lanes (simd::depth_row, where the plane fits them) and its
  // passing pixels go by runs: the LAB's through simd::span_row (they are distinct pixels, and the LAB
  // is not the Z buffer).
  template <class FB>
  [[gnu::flatten]] void depth_and_ambient(const FB& lab, gs::rgba8 ambient);
  // The cached fragments (the runs pixel by pixel, in the same order): triangle t's are
  // frags_[tri_frags_[t], tri_frags_[t + 1]). Built from the runs when first asked for after step 1.
  const std::vector<fragment>& fragments() {
    if (frags_built_) return frags_;
    frags_.clear();
    tri_frags_.assign(1, 0);
    for (std::size_t t = 0; t + 1 < tri_runs_.size(); ++t, tri_frags_.push_back(frags_.size()))
      for (std::size_t i = tri_runs_[t]; i < tri_runs_[t + 1]; ++i)
        for (int k = 0; k < runs_[i].n; ++k)
          frags_.push_back({static_cast<std::int32_t>(t), static_cast<std::int16_t>(runs_[i].x0 + k),
                            static_cast<std::int16_t>(runs_[i].y)});
    frags_built_ = true;
    return frags_;
  }

  // A triangle pass (ZTST = GEQUAL, ZMSK = 1) over `tris` (a layer's, or all); a piece's (SCISSOR_1,
  // texture_stream.hpp) by the scalar loop, compiled per register set with one call site of the pixel.
  template <const pass_regs& Pass, class FB>
  [[gnu::flatten]] void draw(const texture_ref* tex, const std::vector<tri_attr>& attr, const FB& fb,
                             triangle_range tris, const stream_piece* piece = nullptr) {
    if (vectorised() && piece == nullptr) return draw_spans(batch_registers<Pass>, tex, attr, fb, tris);
    constexpr gs::gs_registers regs = Pass.registers();
    const bool cached = piece == nullptr && o_.path == raster_path::cached;
    const std::vector<fragment> cut = cached ? std::vector<fragment>{} : fragments_of(piece, tris);
    const std::span<const fragment> fs = cached ? of(fragments(), tri_frags_, tris) : std::span<const fragment>(cut);
    std::array<pixel_inputs, 64> in;  // the texels and colours of up to 64 fragments, fetched first
    for (std::size_t i = 0; i < fs.size(); i += in.size()) {
      const std::size_t n = std::min(in.size(), fs.size() - i);
      fetch_inputs(tex, attr, &fs[i], n, in.data());
      for (std::size_t k = 0; k < n; ++k) {
        const int x = fs[i + k].x, y = fs[i + k].y;
        std::uint32_t& word = fb(x, y);
        word = gs_pixel(regs, in[k].texel, in[k].cf, word, x, y, o_.model);
        if (pending != nullptr) note_shaded(index(x, y), in[k].texel, in[k].cf);
      }
      ops_ += n;
    }
  }
  // The texel (none without a texture) and the Gouraud colour of fragments f[0, n) (the triangle
  // textures are never the target, so fetching them before the writes changes nothing); not per set.
  struct pixel_inputs {
    gs::rgba8 texel;
    gs::fragment_colour cf;
  };
  [[gnu::noinline]] static void fetch_inputs(const texture_ref* tex, const std::vector<tri_attr>& attr,
                                             const fragment* f, std::size_t n, pixel_inputs* out) {
    for (std::size_t k = 0; k < n; ++k) {
      const int x = f[k].x, y = f[k].y;
      const tri_attr& a = attr[static_cast<std::size_t>(f[k].tri)];
      out[k].cf = a.colour_at(x, y);
      out[k].texel = tex != nullptr ? tex->sample(a.u.at(x, y), a.v.at(x, y)) : gs::rgba8{};
    }
  }
  // The fragments a triangle pass draws, in draw order: with a piece its triangles' in its rectangle
  // (cached, rows in order within each triangle), on the reference path rasterised again and tested.
  [[gnu::noinline]] std::vector<fragment> fragments_of(const stream_piece* piece, triangle_range tris) {
    std::vector<fragment> out;
    const scissor* clip = piece != nullptr ? &piece->area : nullptr;
    const triangle_range range = piece != nullptr ? piece->triangles : tris;  // a piece's: within its layer's
    if (o_.path == raster_path::cached) {
      fragments();
      for (std::uint32_t t = range.first; t < range.end; ++t) {
        const auto end = frags_.begin() + static_cast<std::ptrdiff_t>(tri_frags_[t + 1]);
        auto f = std::lower_bound(frags_.begin() + static_cast<std::ptrdiff_t>(tri_frags_[t]), end, clip->y0,
                                  [](const fragment& g, int y) { return g.y < y; });
        for (; f != end && f->y < clip->y1; ++f)
          if (f->x >= clip->x0 && f->x < clip->x1) out.push_back(*f);
      }
      return out;
    }
    const scissor area = clip == nullptr ? band_
                                         : scissor{std::max(band_.x0, clip->x0), std::max(band_.y0, clip->y0),
                                                   std::min(band_.x1, clip->x1), std::min(band_.y1, clip->y1)};
    for (std::uint32_t t = range.first; t < range.end; ++t) {
      const prepared_triangle& tri = ps_.triangles[t];
      rasterise_triangle(tri.setup, area, [&](int x, int y) {
        if (passes_later_depth_test(tri, x, y))
          out.push_back({static_cast<std::int32_t>(t), static_cast<std::int16_t>(x), static_cast<std::int16_t>(y)});
      });
    }
    return out;
  }

  // A triangle pass drawn with PRIM.FST = 0 (section 3.6's spot light): each triangle's texel
  // coordinates from its S, T, Q (gs::stq_sampler, the packet interpreter's rule), vertex colour
  // `colour`, pixel by pipeline pixel (ZTST = GEQUAL, ZMSK = 1, as draw()).
  template <const pass_regs& Pass, class FB>
  [[gnu::flatten]] void draw_projective(const texture_ref& tex, const std::vector<gs::stq_sampler>& st,
                                        gs::rgba8 colour, const FB& fb) {
    constexpr gs::gs_registers regs = Pass.registers();
    const gs::fragment_colour cf = gs::fragment_colour::flat(colour);
    auto shade = [&](std::size_t t, int x, int y) {
      const auto [u, v] = st[t].at(x, y, o_.model);
      const gs::rgba8 texel = tex.sample(u, v);
      std::uint32_t& word = fb(x, y);
      word = gs_pixel(regs, texel, cf, word, x, y, o_.model);
      if (pending != nullptr) note_shaded(index(x, y), texel, cf);
      ++ops_;
    };
    if (o_.path == raster_path::cached) {
      for (const fragment& f : fragments()) shade(static_cast<std::size_t>(f.tri), f.x, f.y);
      return;
    }
    for (std::size_t t = 0; t < ps_.triangles.size(); ++t)
      rasterise_triangle(ps_.triangles[t].setup, band_, [&](int x, int y) {
        if (passes_later_depth_test(ps_.triangles[t], x, y)) shade(t, x, y);
      });
  }

  // Step 5 (section 3.1): prepared_scene::plain drawn in order with `attr` (plain_colour, its UVs)
  // and ZTST = GEQUAL, ZMSK = 0, every pixel through gs::pixel_pipeline; a pixel it draws shows step
  // 5's triangle (plain[i] = its index) and no longer the DOT3 mesh's (visible_triangle −1).
  template <const pass_regs& Pass, class FB>
  void draw_plain(const texture_ref& tex, const std::vector<tri_attr>& attr, const FB& fb,
                  std::vector<std::int32_t>& plain) {
    constexpr gs::gs_registers regs = Pass.registers();
    for (std::size_t t = 0; t < ps_.plain.size(); ++t) {
      const prepared_triangle& tri = ps_.plain[t];
      const tri_attr& a = attr[t];
      rasterise_triangle(tri.setup, band_, [&](int x, int y) {
        const gs::depth_result d = gs::depth_test(passes::depth_gequal, passes::z_written,
                                                  static_cast<std::uint32_t>(tri.z.at(x, y)), z_.read(x, y));
        if (!d.pass) return;
        if (d.write_z) z_.write(x, y, d.z);
        const std::size_t i = index(x, y);
        const gs::fragment_colour cf = a.colour_at(x, y);
        const gs::rgba8 texel = tex.sample(a.u.at(x, y), a.v.at(x, y));
        std::uint32_t& word = fb(x, y);
        word = gs_pixel(regs, texel, cf, word, x, y, o_.model);
        if (pending != nullptr) note_shaded(i, texel, cf);
        visible_[i] = -1;
        plain[i] = static_cast<std::int32_t>(t);
        ++ops_;
      });
    }
  }

  // A 2D sprite pass with a flat colour over the drawn triangles' bounding rectangle within the band
  // (an engine scissors its post filter to the object; outside it the DPB keeps its clear value and
  // the frame stays 0 = diffuse 0 × LAB); `texel(x, y)` gives the texel the sprite's 1:1 mapping
  // fetches for frame-buffer pixel (x, y).
  template <const pass_regs& Pass, class Texel, class FB>
  [[gnu::flatten]] void sprite(gs::rgba8 colour, Texel&& texel, const FB& fb) {
    sprite_rect<Pass>(colour, sprite_area_, texel, fb);
  }
  // The same over rectangle r clipped to the sprite area (or to `clip`): one of the memory path's
  // tile sprites.
  template <const pass_regs& Pass, class Texel, class FB>
  [[gnu::flatten]] void sprite_rect(gs::rgba8 colour, scissor r, Texel&& texel, const FB& fb,
                                    const scissor* clip = nullptr) {
    constexpr gs::gs_registers regs = Pass.registers();
    const gs::fragment_colour cf = gs::fragment_colour::flat(colour);
    const scissor& a = clip != nullptr ? *clip : sprite_area_;
    r = {std::max(r.x0, a.x0), std::max(r.y0, a.y0), std::min(r.x1, a.x1), std::min(r.y1, a.y1)};
    if (r.x0 >= r.x1 || r.y0 >= r.y1) return;
    if (vectorised() && !scalar_sprites) {
      if constexpr (std::is_same_v<FB, row_view>) {  // rows of adjacent words: the pixels rasterise_sprite visits
        const auto n = static_cast<std::size_t>(r.x1 - r.x0);
        scratch<std::uint32_t> texels(n);
        texels->resize(n);
        for (int y = r.y0; y < r.y1; ++y) {
          for (int x = r.x0; x < r.x1; ++x) (*texels)[static_cast<std::size_t>(x - r.x0)] = texel(x, y).to_u32();
          simd::span_row(batch_registers<Pass>, o_.model, cf, texels->data(), &fb(r.x0, y), r.x0, y, n);
        }
        ops_ += n * static_cast<std::size_t>(r.y1 - r.y0);
        return;
      } else if (fb.address != nullptr) {
        return memory_rows(batch_registers<Pass>, cf, r, texel, fb);
      }
      span_batch batch(batch_registers<Pass>, o_.model);
      rasterise_sprite({r.x0 * 16, r.y0 * 16}, {r.x1 * 16, r.y1 * 16}, r, [&](int x, int y) {
        batch.add(fb(x, y), texel(x, y), cf, x, y);
        ++ops_;
      });
      return;
    }
    rasterise_sprite({r.x0 * 16, r.y0 * 16}, {r.x1 * 16, r.y1 * 16}, r, [&](int x, int y) {
      const gs::rgba8 t = texel(x, y);
      std::uint32_t& word = fb(x, y);
      word = gs_pixel(regs, t, cf, word, x, y, o_.model);
      if (pending != nullptr && in_frame(x, y)) note_shaded(index(x, y), t, cf);
      ++ops_;
    });
  }

  // Fills the band (`whole`) or only the sprite area (where any pass can write) with v, the bits
  // Pass's FBMSK masks kept: on the value path directly, on the memory path as the GS clears, a flat
  // sprite (TME = 0, ABE = 0, RGBAQ = v; step1_ambient writes the whole word, flat_rgb keeps alpha).
  template <const pass_regs& Pass = passes::step1_ambient, class FB>
  void fill(const FB& fb, std::uint32_t v, bool whole = true) {
    static_assert(!Pass.TME && !Pass.ABE && Pass.CLAMP);
    const scissor& a = whole ? band_ : sprite_area_;
    if constexpr (std::is_same_v<FB, row_view>) {
      for (int y = a.y0; y < a.y1; ++y)
        if constexpr (Pass.FBMSK == 0) {
          if (a.x0 < a.x1) std::fill(&fb(a.x0, y), &fb(a.x0, y) + (a.x1 - a.x0), v);
        } else {
          for (int x = a.x0; x < a.x1; ++x) fb(x, y) = (fb(x, y) & Pass.FBMSK) | (v & ~Pass.FBMSK);
        }
    } else {
      sprite_rect<Pass>(
          gs::rgba8::from_u32(v), a, [](int, int) { return gs::rgba8{}; }, fb, &a);
    }
  }

  // The frame program's clears over the frame (the memory's state before step 1): v written directly
  // over the band, the bits of `keep` kept, and with `z` the Z buffer's 24 bits set to 0. They are
  // not sent through gs::pixel_pipeline, so pixel_ops does not count them.
  template <class FB>
  void clear(const FB& fb, std::uint32_t v, std::uint32_t keep, bool z) {
    fill_band(fb, v, keep);
    if (!z) return;
    if (z_.in_memory) return fill_band(z_.memory, 0, 0xFF000000u);  // PSMZ24: bits 0-23
    fill_band(z_.rows, 0, 0xFF000000u);
  }
  // v into the band's pixels of fb, the bits of `keep` kept (band_spans.hpp).
  template <class FB>
  void fill_band(const FB& fb, std::uint32_t v, std::uint32_t keep);

  // Whether (x, y) is a pixel of the frame: sprites clipped to whole pages (the z-trick modes' Z clear,
  // channel_pass.hpp) also draw the buffer's pixels past the frame's right and bottom edges, which the
  // frame-sized records (the trace, the frame's per-pixel vectors) do not have.
  bool in_frame(int x, int y) const { return x < ps_.width && y < ps_.height; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(ps_.width) + static_cast<std::size_t>(x);
  }
  const scissor& band() const { return band_; }
  const scissor& sprite_area() const { return sprite_area_; }
  std::size_t pixel_ops() const { return ops_; }
  void count_ops(std::size_t n) { ops_ += n; }
  const render_options& options() const { return o_; }
  // The SIMD pixel pipeline (render_options::simd; a traced render records every pixel, so it is scalar).
  bool vectorised() const noexcept { return o_.simd && pending == nullptr; }

  // Tracing (render_options::trace): the pass being drawn records its inputs here (frame-sized).
  pass_record* pending = nullptr;
  // Sprites whose texel fetch reads memory the sprite writes (the memory path's channel passes) go
  // pixel by pixel: span_batch writes a batch only when it is flushed.
  bool scalar_sprites = false;
  void note_shaded(std::size_t i, gs::rgba8 texel, const gs::fragment_colour& cf) {
    pending->texel[i] = texel.to_u32();
    const gs::gouraud_channel c[4] = {cf.r, cf.g, cf.b, cf.a};
    for (std::size_t k = 0; k < 4; ++k) pending->colour[4 * i + k] = static_cast<std::uint16_t>(c[k].value());
    pending->shaded[i] = 1;
  }

  // The bounding rectangle of every drawn triangle's pixels, within the band (may be empty).
  static scissor drawn_area(const prepared_scene& ps, scissor band) {
    scissor a{band.x1, band.y1, band.x0, band.y0};
    for (const prepared_triangle& t : ps.triangles)
      for (const xy124& v : t.setup.v) {
        a.x0 = std::min(a.x0, ceil_124(v.x) - 1);
        a.y0 = std::min(a.y0, ceil_124(v.y) - 1);
        a.x1 = std::max(a.x1, ceil_124(v.x) + 1);
        a.y1 = std::max(a.y1, ceil_124(v.y) + 1);
      }
    return {std::max(a.x0, band.x0), std::max(a.y0, band.y0), std::min(a.x1, band.x1), std::min(a.y1, band.y1)};
  }

 private:
  // The registers the SIMD path reads at run time: a copy of its own, so that the scalar path's
  // compile-time `regs` never has its address taken (g++ then folds gs::pixel_pipeline as before).
  template <const pass_regs& Pass>
  static constexpr gs::gs_registers batch_registers = Pass.registers();
  // draw() through span_batch and the span engine, and a triangle's runs through the span engine when it is
  // in its domain (band_spans.hpp).
  template <class FB>
  [[gnu::noinline, gnu::flatten]] void draw_spans(const gs::gs_registers& regs, const texture_ref* tex,
                                                  const std::vector<tri_attr>& attr, const FB& fb, triangle_range tris);
  template <class Texel>
  void memory_rows(const gs::gs_registers& regs, const gs::fragment_colour& cf, scissor r, Texel&& texel,
                   const memory_view& fb);
  bool span_engine(const gs::gs_registers& regs, const tri_attr& a, const simd::nearest_texture& tex,
                   std::span<const run> rs, const simd::span_target& fb);

  // The pixels a triangle can cover within the band: its vertices' bounding box, rounded out.
  scissor covered_rectangle(const gs::triangle_setup& s) const noexcept {
    const scissor b = vertex_bounds(s);
    return {std::max(band_.x0, b.x0), std::max(band_.y0, b.y0), std::min(band_.x1, b.x1), std::min(band_.y1, b.y1)};
  }
  // The depth test of every pass after step 1 (GEQUAL, ZMSK = 1: Z is only read), of a fragment's depth z
  // at (x, y), or of triangle tri's there.
  bool passes_later_depth_test(std::uint32_t z, int x, int y) const noexcept {
    return gs::depth_test(passes::depth_gequal, passes::z_masked, z, z_.read(x, y)).pass;
  }
  bool passes_later_depth_test(const prepared_triangle& tri, int x, int y) const noexcept {
    return passes_later_depth_test(static_cast<std::uint32_t>(tri.z.at(x, y)), x, y);
  }

  const prepared_scene& ps_;
  const render_options& o_;
  scissor band_, sprite_area_;
  z_view z_;
  std::vector<std::int32_t>& visible_;
  // Triangle t's fragments are frags_[tri_frags_[t], tri_frags_[t + 1]), its runs (frags_ as runs along a row, in the
  // same order) runs_[tri_runs_[t], tri_runs_[t + 1]); their storage is kept between frames (scratch.hpp).
  scratch<fragment> frag_store_;
  scratch<run> run_store_;
  scratch<std::size_t> tri_frag_store_, tri_run_store_;
  std::vector<fragment>& frags_ = *frag_store_;
  std::vector<run>& runs_ = *run_store_;
  std::vector<std::size_t>&tri_frags_ = *tri_frag_store_, &tri_runs_ = *tri_run_store_;
  bool frags_built_ = false;
  std::size_t ops_ = 0;
};

}  // namespace gsdot3::pipeline::detail

#include "pipeline/band_spans.hpp"  // IWYU pragma: export
#include "pipeline/band_step1.hpp"  // IWYU pragma: export
