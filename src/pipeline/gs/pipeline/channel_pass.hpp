// pipeline/channel_pass.hpp — render.cpp's frame buffers and its passes that read a frame buffer
// as a texture: step 2.4's post filter, the ILP read of 2.6 and step 4's channel move (a byte of
// each pixel through a palette), on the value path (the byte of the same pixel's word) and on the
// memory path (gs_memory's channel-fetch sprites), and the memory path's copy of the LAB into the
// output. Internal to render.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "gs_arith/depth_test.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/overlay.hpp"
#include "gs_memory/texture_buffer.hpp"
#include "gs_memory/texture_wrap.hpp"
#include "gs_memory/transfer.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/pass_table.hpp"

namespace gsdot3::pipeline::detail {

inline gs::u8 byte(int v) { return gs::u8::from_wrapped(v); }

template <class FB>
struct frame_buffers {
  z_view zb;
  FB lab, dpb, diff, out;
  // draw_buffers::one: the free alphas (method.hpp) that hold light k's dot layer, then the LAB's
  // channel k. Value path: the alphas of the DPB, LAB and output vectors (none of them drawn as such
  // in that mode but the output). Memory path: the buffer at FBP 0 (the display's other buffer: the
  // output at 2P is the displayed one), the Z buffer's words at ZBP as PSMCT32 (PSMZ24 leaves their
  // top byte unused, so writing it never changes a Z) and the output's own.
  FB alpha_plane[3];
  gs::mem::local_memory* memory = nullptr;               // the memory path's local memory, else null
  buffer_layout layout;                                  // the memory path's buffers (gs_inputs.hpp)
  const gs::mem::texel_addresses* page_as_t8 = nullptr;  // the memory path: a page of the DPB / LAB as PSMT8 (BP 0)
  dpb_clear_mode clear = dpb_clear_mode::explicit_clear;
};

inline constexpr bool in_memory(const row_view&) { return false; }
inline constexpr bool in_memory(const memory_view&) { return true; }

// A sprite pass whose texel is byte `channel` of each pixel of `src` through `clut`, into `dst`.
// Value level: the byte of the same pixel's word. Memory path: gs_memory's channel-fetch sprites
// (8×2 tiles per page, the page read as PSMT8 with TBP0 = its base, TBW = 2·FBW, TW = 7, TH = 6).
// With the SIMD units, the rows go through the span engine's channel row (gs_simd/span_draw.hpp: the
// same texel, the CLUT's entry i as its word).
template <const pass_regs& Pass>
inline void channel_pass(band_renderer& r, const frame_buffers<row_view>&, gs::rgba8 colour,
                         const gs::clut_buffer& clut, unsigned channel, const row_view& src, const row_view& dst) {
  const scissor& a = r.sprite_area();
  if (!r.vectorised() || a.x0 >= a.x1) {
    r.sprite<Pass>(
        colour, [&](int x, int y) { return gs::clut_t8(clut, byte(static_cast<int>(src(x, y) >> (8 * channel)))); },
        dst);
    return;
  }
  static constexpr gs::gs_registers regs = Pass.registers();
  const std::array<std::uint32_t, 256> words = clut_words(clut);
  const auto n = static_cast<std::size_t>(a.x1 - a.x0);
  for (int y = a.y0; y < a.y1; ++y)
    simd::span_channel_row(regs, r.options().model, gs::fragment_colour::flat(colour), &src(a.x0, y), channel,
                           words.data(), &dst(a.x0, y), a.x0, y, n);
  r.count_ops(n * static_cast<std::size_t>(a.y1 - a.y0));
}
// The memory path's channel-fetch sprites in SIMD lanes (simd::span_fetched), page by page. With the
// source's and the target's FBP on whole pages every page repeats one pattern: sprite pixel i (16·k +
// 8·dy + dx of sprite k) is drawn at (x[i], y[i]) from the page's corner, fetches byte read[i] of the
// source page (8 KiB) and writes word word[i] of the target page (a 32-bit page is 2048 words in a
// row; gs_memory/fast_address.hpp: the page term is linear). No pixel then writes a word another one
// fetches, so the order of the pixels changes nothing, when the two pages are different (their words
// are disjoint) or when they are one and each pixel fetches a byte of the very word it writes (`own`:
// a buffer's channel into itself).
class fetch_pages {
 public:
  static constexpr std::size_t pixels = 16 * 128;
  // fetched[i]: the page-relative byte pixel i fetches (texel_addresses at BP 0); corner(sprite): where
  // the sprite is drawn on page (0, 0).
  template <class Corner>
  fetch_pages(const gs::mem::channel_fetch& f, const std::array<std::uint32_t, pixels>& fetched, const memory_view& src,
              const memory_view& dst, Corner&& corner)
      : applies_(dst.address != nullptr && src.bp % 32 == 0 && dst.bp % 32 == 0) {
    for (std::size_t k = 0; k < f.sprites.size() && applies_; ++k) {
      const std::array<int, 2> at = corner(f.sprites[k]);
      for (std::size_t j = 0; j < 16; ++j) {
        const std::size_t i = 16 * k + j;
        x_[i] = at[0] + static_cast<int>(j % 8), y_[i] = at[1] + static_cast<int>(j / 8);
        read_[i] = fetched[i], word_[i] = dst.word_of(x_[i], y_[i]) - dst.page_of(x_[i], y_[i]);
        applies_ = applies_ && read_[i] < gs::mem::page_bytes && x_[i] >= 0 && x_[i] < 64 && y_[i] >= 0 && y_[i] < 32;
        own_ = own_ && read_[i] / 4 == word_[i];
      }
    }
  }
  bool applies() const noexcept { return applies_; }
  // Page (px, py) of the sprites clipped to `clip`, drawn with Pass; false (nothing drawn) when its
  // pixels may not be drawn in lanes.
  template <const pass_regs& Pass>
  bool draw(band_renderer& r, gs::rgba8 colour, const std::array<std::uint32_t, 256>& clut, int px, int py,
            std::uint32_t src_page, const memory_view& dst, const scissor& clip) const {
    static constexpr gs::gs_registers regs = Pass.registers();
    const int x0 = 64 * px, y0 = 32 * py;
    const auto read_base = src_page * gs::mem::page_bytes % gs::mem::memory_bytes;
    const std::uint32_t word_base = dst.page_of(x0, y0);
    if (read_base / 4 == word_base && !own_) return false;
    const gs::fragment_colour cf = gs::fragment_colour::flat(colour);
    auto lanes = [&](const auto& read, const auto& word, const auto& x, const auto& y, std::size_t n) {
      simd::span_fetched(regs, r.options().model, cf, dst.words, read_base, read.data(), clut.data(), word_base,
                         word.data(), x0, y0, x.data(), y.data(), n);
      r.count_ops(n);
    };
    if (clip.x0 <= x0 && x0 + 64 <= clip.x1 && clip.y0 <= y0 && y0 + 32 <= clip.y1) {
      lanes(read_, word_, x_, y_, pixels);
      return true;
    }
    std::array<std::uint32_t, pixels> read, word;  // the page's pixels within the clip
    std::array<std::int32_t, pixels> x, y;
    std::size_t n = 0;
    for (std::size_t i = 0; i < pixels; ++i)
      if (const int cx = x0 + x_[i], cy = y0 + y_[i]; cx >= clip.x0 && cx < clip.x1 && cy >= clip.y0 && cy < clip.y1)
        read[n] = read_[i], word[n] = word_[i], x[n] = x_[i], y[n] = y_[i], ++n;
    lanes(read, word, x, y, n);
    return true;
  }

 private:
  bool applies_, own_ = true;
  std::array<std::uint32_t, pixels> read_{}, word_{};
  std::array<std::int32_t, pixels> x_{}, y_{};
};

// The memory path. A source drawn in PSMZ32 (src.z) has logical pixel L in the word of PSMCT32
// pixel zsigma(L) (gs_memory/overlay.hpp): the tile that fetches PSMCT32 pixel M is drawn at zsigma(M) (the sprites'
// XYZ in the Z layout). z_clear: the ILP pass of the z-trick modes, also writing Z = 0x00808080 into the DPB as PSMZ24
// at every fragment (after its texel fetch). In the z-trick modes the texel fetches go through gs_memory's
// texture_page_buffer model (model option texture_buffer).
template <const pass_regs& Pass>
inline void channel_pass(band_renderer& r, const frame_buffers<memory_view>& fb, gs::rgba8 colour,
                         const gs::clut_buffer& clut, unsigned channel, const memory_view& src, const memory_view& dst,
                         bool z_clear = false, gs::texture_buffer tb = gs::texture_buffer::per_fragment) {
  static constexpr gs::mem::channel_fetch layout[4] = {
      gs::mem::channel_fetch_sprites(0), gs::mem::channel_fetch_sprites(1), gs::mem::channel_fetch_sprites(2),
      gs::mem::channel_fetch_sprites(3)};
  const gs::mem::channel_fetch& f = layout[channel];
  gs::mem::local_memory& mem = *fb.memory;
  const gs::mem::buffer zbuf{fixed::uint<14>::from_wrapped(fb.dpb.bp), fixed::uint<6>::from_wrapped(fb.dpb.bw),
                             gs::mem::psm::PSMZ24};
  const bool buffered = fb.clear != dpb_clear_mode::explicit_clear;
  const scissor& a = r.sprite_area();
  // With the Z clear the ILP sprites cover every page the area touches (the paper's per-page
  // primitives, section 3.3), so that the Z writes clear whole pages.
  const scissor pages = whole_pages(a);
  r.scalar_sprites = true;  // the texel fetches read the memory the sprites write (span_batch.hpp)
  // In lanes where a page allows (fetch_pages): not with the Z clear's writes between the fetches,
  // nor with a texture buffer that is not the memory itself.
  const bool lanes = r.vectorised() && !z_clear && (!buffered || tb == gs::texture_buffer::per_fragment);
  // The byte of the page (at TBP0 = 0) each sprite pixel fetches, through CLAMP_1 and the PSMT8
  // address: sprite k's pixel (dx, dy) at 16·k + 8·dy + dx. The sprites and their texels are the
  // same on every page, which only moves TBP0 (texel_addresses::byte adds it).
  static_assert([] {
    for (const gs::mem::channel_fetch& c : layout)
      for (const gs::mem::fetch_sprite& sp : c.sprites)
        if (sp.x1 - sp.x0 != 8 || sp.y1 - sp.y0 != 2) return false;
    return true;
  }());
  std::array<std::uint32_t, 16 * 128> fetched{};
  for (std::size_t k = 0; k < f.sprites.size(); ++k)
    for (std::int32_t dy = 0; dy < 2; ++dy)
      for (std::int32_t dx = 0; dx < 8; ++dx) {
        const gs::mem::fetch_sprite& sp = f.sprites[k];
        const auto u = gs::mem::wrap_texel(f.CLAMP.WMS, sp.u0 + dx, fixed::u4::literal(7), f.CLAMP.MINU, f.CLAMP.MAXU);
        const auto v = gs::mem::wrap_texel(f.CLAMP.WMT, sp.v0 + dy, fixed::u4::literal(6), f.CLAMP.MINV, f.CLAMP.MAXV);
        fetched[16 * k + static_cast<std::size_t>(8 * dy + dx)] = fb.page_as_t8->byte(u, v, 0);
      }
  // Where sprite sp of page (px, py) is drawn: the PSMCT32 pixel it fetches, in the Z layout through zsigma.
  auto drawn_at = [&](const gs::mem::fetch_sprite& sp, int px, int py) {
    const int mx = px * 64 + static_cast<int>(sp.x0), my = py * 32 + static_cast<int>(sp.y0);
    return src.z ? gs::mem::zsigma(mx, my) : std::array<int, 2>{mx, my};
  };
  std::optional<fetch_pages> pattern;
  std::array<std::uint32_t, 256> words{};
  if (lanes) {
    pattern.emplace(f, fetched, src, dst, [&](const gs::mem::fetch_sprite& sp) { return drawn_at(sp, 0, 0); });
    if (pattern->applies()) {
      words = clut_words(clut);
    } else {
      pattern.reset();
    }
  }
  for (int py = a.y0 / 32; py * 32 < a.y1; ++py)
    for (int px = a.x0 / 64; px * 64 < a.x1; ++px) {
      const std::uint32_t page = static_cast<std::uint32_t>(px) + static_cast<std::uint32_t>(py) * src.bw;
      const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(src.bp + 32 * page),
                                fixed::uint<6>::from_wrapped(2 * src.bw), gs::mem::psm::PSMT8};
      if (pattern && pattern->draw<Pass>(r, colour, words, px, py, tex.BP.value() / 32, dst, a)) continue;
      gs::mem::texture_page_buffer texels(buffered ? tb : gs::texture_buffer::per_fragment, mem,
                                          (src.bp + 32 * page) * 256, gs::mem::page_bytes);
      for (std::size_t k = 0; k < f.sprites.size(); ++k) {
        const gs::mem::fetch_sprite& sp = f.sprites[k];
        const std::uint32_t* sprite_texels = &fetched[16 * k];
        const std::array<int, 2> drawn = drawn_at(sp, px, py);
        const int x0 = drawn[0], y0 = drawn[1];  // plain ints: clang 14 cannot capture structured bindings
        const int w = static_cast<int>(sp.x1 - sp.x0), h = static_cast<int>(sp.y1 - sp.y0);
        r.sprite_rect<Pass>(
            colour, {x0, y0, x0 + w, y0 + h},
            [&](int x, int y) {
              const std::uint32_t at = sprite_texels[8 * (y - y0) + (x - x0)] + tex.BP.value() * gs::mem::block_bytes;
              const std::uint8_t index = texels.fetch(at % gs::mem::memory_bytes);
              if (z_clear) {  // ZBUF = the DPB (PSMZ24), Z = 0x00808080, ZTST = ALWAYS
                const auto zx = static_cast<std::uint32_t>(x), zy = static_cast<std::uint32_t>(y);
                const gs::depth_result d = gs::depth_test(passes::depth_always, passes::z_written, passes::clear_dpb,
                                                          mem.read_pixel(zbuf, zx, zy));
                if (d.write_z) mem.write_pixel(zbuf, zx, zy, d.z);
              }
              return gs::clut_t8(clut, gs::u8::from_wrapped(index));
            },
            dst, z_clear ? &pages : nullptr);
      }
    }
  r.scalar_sprites = false;
}

// Two-pass step 2.4a: n'_a into R, G and B — the DPB `dpb` read as PSMT8H (its own alpha byte at the
// same pixel: gs::t8h_index on the value path; on the memory path the PSMT8H read of the DPB's page, in
// the Z layout at the word of logical (x, y)) through `clut`, one sprite over the sprite area.
template <const pass_regs& Pass>
void alpha_into_rgb(band_renderer& r, const frame_buffers<row_view>&, const row_view& dpb,
                    const gs::clut_buffer& clut) {
  r.sprite<Pass>(
      passes::white, [&](int x, int y) { return gs::clut_t8(clut, gs::t8h_index(dpb(x, y))); }, dpb);
}
template <const pass_regs& Pass>
void alpha_into_rgb(band_renderer& r, const frame_buffers<memory_view>& fb, const memory_view& dpb,
                    const gs::clut_buffer& clut) {
  const gs::mem::buffer t8h{fixed::uint<14>::from_wrapped(dpb.bp), fixed::uint<6>::from_wrapped(dpb.bw),
                            gs::mem::psm::PSMT8H};
  r.sprite<Pass>(
      passes::white,
      [&](int x, int y) {
        const auto [tx, ty] = dpb.z ? gs::mem::zsigma(x, y) : std::array<int, 2>{x, y};
        return gs::clut_t8(
            clut, byte(fb.memory->read_pixel(t8h, static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty))));
      },
      dpb);
}

// The memory path's copy of the LAB into the output over `area` (before step 4): gs_inputs.hpp's
// lab_to_output, the transfer the packet stream writes, run through gs_memory's local_to_local.
inline void copy_lab(const frame_buffers<memory_view>& fb, const scissor& area) {
  if (const std::optional<lab_copy> c = lab_to_output(fb.layout, area, fb.lab.z))
    gs::mem::local_to_local(*fb.memory, c->BITBLTBUF, c->TRXPOS, c->TRXREG, lab_copy::TRXDIR);
}

}  // namespace gsdot3::pipeline::detail
