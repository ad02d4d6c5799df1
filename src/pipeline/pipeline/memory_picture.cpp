#include "pipeline/memory_picture.hpp"

#include <cstdint>

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
      const bool edge = scale >= 3 && (px % (scale * static_cast<int>(blk.w)) == 0 || py % (scale * static_cast<int>(blk.h)) == 0);
      for (int k = 0; k < 3; ++k)
        img.data[(static_cast<std::size_t>(py) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(px)) * 3 + static_cast<std::size_t>(k)] =
            edge ? 0 : rgb[k];
    }
  return img;
}

}  // namespace gsdot3::pipeline
