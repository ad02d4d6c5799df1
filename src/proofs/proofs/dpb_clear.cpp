#include "proofs/dpb_clear.hpp"

#include <memory>
#include <vector>

#include "gs_memory/address.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/overlay.hpp"
#include "gs_memory/texture_buffer.hpp"
#include "gs_memory/texture_wrap.hpp"

namespace gsdot3::proofs {

namespace mem = gs::mem;

const char* name(dpb_clear v) noexcept {
  switch (v) {
    case dpb_clear::explicit_clear: return "explicit";
    case dpb_clear::z_trick: return "z-trick";
    case dpb_clear::z_trick_psmz32: return "z-trick-psmz32";
  }
  return "?";
}

namespace {

mem::buffer page_buffer(std::uint32_t bp, std::uint32_t bw, mem::psm p) {
  return {fixed::uint<14>::from_wrapped(bp), fixed::uint<6>::from_wrapped(bw), p};
}

}  // namespace

// gs_memory's overlay of a PSMCT32 page on a PSMZ32 page: for PSMCT32 pixel p, the PSMZ32 pixel
// of the same word (both formats 32-bit, so bit 0 of it).
int zsigma(int p) {
  static const std::vector<mem::overlay_cell> cells = mem::page_overlay(mem::psm::PSMZ32, mem::psm::PSMCT32);
  const mem::overlay_cell& c = cells[static_cast<std::size_t>(p)];
  return static_cast<int>(c.y) * 64 + static_cast<int>(c.x);
}

ilp_pass run_ilp_pass(const page_words& dpb_before, dpb_clear variant, mem::psm zbuf_psm, gs::texture_buffer tb) {
  thread_local std::unique_ptr<mem::local_memory> memory = std::make_unique<mem::local_memory>();
  mem::local_memory& m = *memory;
  const mem::buffer dpb = page_buffer(0, 1, mem::psm::PSMCT32);
  const mem::buffer lab =
      page_buffer(32, 1, variant == dpb_clear::z_trick_psmz32 ? mem::psm::PSMZ32 : mem::psm::PSMCT32);
  const mem::buffer lab_ct = page_buffer(32, 1, mem::psm::PSMCT32);
  const mem::buffer zbuf = page_buffer(0, 1, zbuf_psm);
  const mem::buffer tex = page_buffer(0, 2, mem::psm::PSMT8);  // TBP0 = DBP, TBW = 2·FBW
  for (int p = 0; p < page_pixels; ++p) {
    m.write_pixel(dpb, p % 64, p / 64, dpb_before[static_cast<std::size_t>(p)]);
    m.write_pixel(lab_ct, p % 64, p / 64, 0);
  }
  ilp_pass out;
  static constexpr mem::channel_fetch red = mem::channel_fetch_sprites(0);
  mem::texture_page_buffer buffer(tb, m, 0, mem::page_bytes);
  for (const mem::fetch_sprite& s : red.sprites)
    for (std::uint32_t y = s.y0; y < s.y1; ++y)
      for (std::uint32_t x = s.x0; x < s.x1; ++x) {
        const int p = static_cast<int>(y * 64 + x);                   // the DPB pixel this fragment reads
        const int q = variant == dpb_clear::z_trick ? zsigma(p) : p;  // where it is drawn
        const auto u = mem::wrap_texel(red.CLAMP.WMS, s.u0 + static_cast<std::int32_t>(x - s.x0), fixed::u4::literal(7),
                                       red.CLAMP.MINU, red.CLAMP.MAXU);
        const auto v = mem::wrap_texel(red.CLAMP.WMT, s.v0 + static_cast<std::int32_t>(y - s.y0), fixed::u4::literal(6),
                                       red.CLAMP.MINV, red.CLAMP.MAXV);
        const std::uint8_t r = buffer.fetch(mem::locate(tex, u, v).byte);
        out.fetched[static_cast<std::size_t>(p)] = r;
        const auto qx = static_cast<std::uint32_t>(q % 64), qy = static_cast<std::uint32_t>(q / 64);
        m.write_pixel(lab, qx, qy, static_cast<std::uint32_t>(p + 1) << 8 | r);
        if (variant != dpb_clear::explicit_clear) m.write_pixel(zbuf, qx, qy, 0x00808080u);
      }
  for (int p = 0; p < page_pixels; ++p) {
    out.dpb_after[static_cast<std::size_t>(p)] = m.read_pixel(dpb, p % 64, p / 64);
    out.lab[static_cast<std::size_t>(p)] = m.read_pixel(lab_ct, p % 64, p / 64);
  }
  return out;
}

}  // namespace gsdot3::proofs
