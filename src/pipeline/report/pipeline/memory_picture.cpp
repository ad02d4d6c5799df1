#include "pipeline/memory_picture.hpp"

#include <cstdint>
#include <stdexcept>

#include "gs_memory/local_memory.hpp"
#include "gs_memory/overlay.hpp"

namespace gsdot3::pipeline {

image page_overlay_image(gs::mem::psm base, gs::mem::psm view, std::string_view colour, int scale) {
  namespace mem = gs::mem;
  constexpr std::uint8_t quarter_rgb[4][3] = {{230, 50, 50}, {50, 200, 60}, {60, 90, 240}, {200, 200, 200}};
  const auto cells = mem::page_overlay(base, view);
  const mem::extent pv = mem::page_size(mem::layout_of(view)), pb = mem::page_size(mem::layout_of(base));
  const mem::extent blk = mem::block_size(mem::layout_of(view));
  const unsigned ub = mem::unit_bits(mem::layout_of(base));
  image img;
  img.width = static_cast<int>(pv.w) * scale;
  img.height = static_cast<int>(pv.h) * scale;
  img.data.assign(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 3, 0);
  for (int py = 0; py < img.height; ++py)
    for (int px = 0; px < img.width; ++px) {
      const auto u = static_cast<std::uint32_t>(px / scale), v = static_cast<std::uint32_t>(py / scale);
      const mem::overlay_cell& c = cells[v * pv.w + u];
      std::uint8_t rgb[3];
      if (colour == "channel") {
        const unsigned q = c.bit * 4 / (ub < 8 ? 8 : ub) % 4;
        const unsigned shade = 120 + 135 * (c.x % 8) / 7;
        for (int k = 0; k < 3; ++k) rgb[k] = static_cast<std::uint8_t>(quarter_rgb[q][k] * shade / 255);
      } else {
        rgb[0] = static_cast<std::uint8_t>(255 * c.x / (pb.w - 1));
        rgb[1] = static_cast<std::uint8_t>(255 * c.y / (pb.h - 1));
        rgb[2] = static_cast<std::uint8_t>(c.bit * 255 / 28);
      }
      const bool edge =
          scale >= 3 && (px % (scale * static_cast<int>(blk.w)) == 0 || py % (scale * static_cast<int>(blk.h)) == 0);
      for (int k = 0; k < 3; ++k)
        img.data[(static_cast<std::size_t>(py) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(px)) *
                     3 +
                 static_cast<std::size_t>(k)] = edge ? 0 : rgb[k];
    }
  return img;
}

dpb_pictures post_filter_dpb_pictures(const std::vector<pass_record>& trace, int w, int h, bool z_layout) {
  namespace mem = gs::mem;
  const pass_record* dpb = nullptr;
  for (const pass_record& p : trace) {
    if (p.light == 0 && p.label.rfind("2.4 R += G", 0) == 0) break;
    if (p.light == 0 && p.target == "DPB") dpb = &p;
  }
  if (dpb == nullptr) throw std::logic_error("memory picture: the trace has no DPB pass before light 0's post filter");
  mem::local_memory m;
  const auto fbw = fixed::uint<6>::from_wrapped((w + 63) / 64);
  const mem::buffer drawn{{}, fbw, z_layout ? mem::psm::PSMZ32 : mem::psm::PSMCT32}, shown{{}, fbw, mem::psm::PSMCT32};
  const mem::buffer texture{{}, fixed::uint<6>::from_wrapped(2 * fbw.value()), mem::psm::PSMT8};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      m.write_pixel(drawn, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                    dpb->word[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)]);
  dpb_pictures out;
  out.display = {w, h, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint32_t v = m.read_pixel(shown, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      for (std::size_t k = 0; k < 3; ++k)
        out.display
            .data[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3 + k] =
            static_cast<std::uint8_t>(v >> (8 * k));
    }
  out.as_psmt8 = {2 * w, 2 * h, 1,
                  std::vector<std::uint8_t>(static_cast<std::size_t>(4 * w) * static_cast<std::size_t>(h))};
  for (int v = 0; v < 2 * h; ++v)
    for (int u = 0; u < 2 * w; ++u)
      out.as_psmt8.data[static_cast<std::size_t>(v) * static_cast<std::size_t>(2 * w) + static_cast<std::size_t>(u)] =
          static_cast<std::uint8_t>(
              m.read_pixel(texture, static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)));
  return out;
}

}  // namespace gsdot3::pipeline
