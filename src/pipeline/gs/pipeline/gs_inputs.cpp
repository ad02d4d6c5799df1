#include "pipeline/gs_inputs.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "gs_memory/clut_load.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/table_cache.hpp"

namespace gsdot3::pipeline {

namespace {

std::vector<std::uint8_t> bytes_of(const std::vector<std::uint32_t>& words) {
  std::vector<std::uint8_t> b(words.size() * 4);
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k) b[4 * i + k] = static_cast<std::uint8_t>(words[i] >> (8 * k));
  return b;
}

gs::clut_buffer index_in_alpha() {
  gs::clut_buffer p{};
  for (int i = 0; i < 256; ++i) {
    const auto v = gs::u8::from_wrapped(i);
    p[static_cast<std::size_t>(i)] = {v, v, v, v};
  }
  return p;
}

}  // namespace

std::optional<lab_copy> lab_to_output(const buffer_layout& b, const scissor& area, bool lab_in_z_layout) {
  if (area.x0 >= area.x1 || area.y0 >= area.y1) return std::nullopt;
  lab_copy c;
  const gs::mem::buffer lab = b.colour(b.lab()), out = b.colour(b.output());
  c.BITBLTBUF.SBP = lab.BP;
  c.BITBLTBUF.SBW = lab.BW;
  c.BITBLTBUF.SPSM = lab_in_z_layout ? gs::mem::psm::PSMZ32 : gs::mem::psm::PSMCT32;
  c.BITBLTBUF.DBP = out.BP;
  c.BITBLTBUF.DBW = out.BW;
  c.BITBLTBUF.DPSM = out.PSM;
  c.TRXPOS.SSAX = c.TRXPOS.DSAX = fixed::uint<11>::from_wrapped(area.x0);
  c.TRXPOS.SSAY = c.TRXPOS.DSAY = fixed::uint<11>::from_wrapped(area.y0);
  c.TRXREG = {fixed::uint<12>::from_wrapped(area.x1 - area.x0), fixed::uint<12>::from_wrapped(area.y1 - area.y0)};
  return c;
}

std::array<gs::clut_buffer*, 8> palettes(gs_inputs& in, std::size_t layer) {
  layer_palettes& p = in.layers.at(layer);
  return {&p[0], &p[1], &p[2], &p[3], &p[4], &in.ilp, &in.grey, &in.alpha_index};
}
std::array<const gs::clut_buffer*, 8> palettes(const gs_inputs& in, std::size_t layer) {
  const layer_palettes& p = in.layers.at(layer);
  return {&p[0], &p[1], &p[2], &p[3], &p[4], &in.ilp, &in.grey, &in.alpha_index};
}

gs::mem::psm index_psm(const normal_map& nm) { return nm.bits == 4 ? gs::mem::psm::PSMT4 : gs::mem::psm::PSMT8; }

std::size_t normal_map_count(const gs_inputs& in) { return in.component_maps[0].empty() ? 1 : 3; }
std::size_t normal_map_of(const gs_inputs& in, clut_slot c) {
  if (normal_map_count(in) == 1) return 0;
  switch (c) {
    case clut_slot::axis_x: return 0;
    case clut_slot::axis_y: return 1;
    case clut_slot::axis_z: return 2;
    default: throw std::logic_error("a 24-bit map's component maps are read through the axis palettes only");
  }
}
std::span<const std::uint8_t> normal_map_texels(const gs_inputs& in, std::size_t layer, std::size_t k) {
  const std::size_t n = layer_texels(*in.nm);
  const std::span<const std::uint8_t> all = normal_map_count(in) == 1 ? in.nm->index : in.component_maps.at(k);
  return all.subspan(layer * n, n);
}

gs_inputs make_inputs(const scene& s, method m, const render_options& o) {
  gs_inputs in;
  in.nm = &s.normals;
  in.diffuse = &s.diffuse;
  in.ilp = intensity_palette(o.specular_power);
  in.grey = identity_palette();
  in.alpha_index = index_in_alpha();
  for (std::size_t l = 0; l < layers(s.normals); ++l) {
    const std::vector<glm::vec3> palette = layer_palette(s.normals, l);
    layer_palettes& p = in.layers.emplace_back();
    auto& pos = p[static_cast<std::size_t>(clut_slot::pos)];
    auto& neg = p[static_cast<std::size_t>(clut_slot::neg)];
    auto axis = [&](int a) -> gs::clut_buffer& { return p[static_cast<std::size_t>(clut_slot::axis_x) + a]; };
    switch (passes::describe(m).palettes) {
      case passes::palette_kind::two_pass:
        pos = two_pass_palette(palette, false);
        neg = two_pass_palette(palette, true);
        break;
      case passes::palette_kind::three_pass:
        pos = two_pass_palette(palette, false);
        neg = two_pass_palette(palette, true);
        axis(0) = three_pass_terms_palette(palette);
        break;
      case passes::palette_kind::none: break;
      case passes::palette_kind::signed_side:
        pos = signed_side_palette(palette, false);
        neg = signed_side_palette(palette, true);
        break;
      case passes::palette_kind::reordered_axes:
        for (int a = 0; a < 3; ++a)
          axis(a) = s.normals.bits == 24 ? component_ramp_palette() : reordered_palette(palette, a);
        break;
    }
  }
  if (passes::describe(m).palettes == passes::palette_kind::reordered_axes && s.normals.bits == 24)
    for (int a = 0; a < 3; ++a)
      in.component_maps[static_cast<std::size_t>(a)] = component_map(s.normals.unquantised, a);
  for (const passes::light_pass& p : passes::describe(m).light)
    if (p.source == passes::pass_source::sphere_map) in.sphere = sphere_map(64, 64);
  if (std::any_of(s.lights.begin(), s.lights.end(), [](const scene_light& l) { return l.kind == light_kind::spot; }))
    in.spot = spot_map();
  return in;
}

gs_inputs place_inputs(const gs_inputs& direct, std::uint32_t first) {
  gs_inputs in = direct;
  std::uint32_t next = first;
  auto place = [&](int w, int h, gs::mem::psm p) {
    const gs::mem::extent pg = gs::mem::page_size(gs::mem::layout_of(p));
    auto bw = static_cast<std::uint32_t>((w + 63) / 64);
    if (pg.w == 128) bw = std::max(2u, bw + bw % 2);  // a PSMT8 page is 128 wide: an even TBW
    const std::uint32_t pages = bw * 64 / pg.w * ((static_cast<std::uint32_t>(h) + pg.h - 1) / pg.h);
    const gs::mem::buffer b{fixed::uint<14>::from_wrapped(next), fixed::uint<6>::from_wrapped(bw), p};
    next += 32 * pages;
    return b;
  };
  auto palettes_page = [&] {
    in.cbp.assign(in.layers.size(), {});
    for (std::size_t l = 0; l < in.layers.size(); ++l) {
      const gs::mem::buffer page = place(64, 32, gs::mem::psm::PSMCT32);  // one page: 8 CLUTs of 4 blocks
      for (std::size_t k = 0; k < in.cbp[l].size(); ++k)
        in.cbp[l][k] = k < normal_map_palettes || l == 0
                           ? static_cast<std::uint32_t>(page.BP.value()) + 4 * static_cast<std::uint32_t>(k)
                           : in.cbp[0][k];
    }
  };
  in.nm_at.clear();
  for (std::size_t t = 0; t < in.layers.size() * normal_map_count(direct); ++t)
    in.nm_at.push_back(place(direct.nm->width, direct.nm->height, index_psm(*direct.nm)));
  if (!direct.sphere.empty()) in.sphere_at = place(64, 64, gs::mem::psm::PSMCT32);
  if (!direct.spot.empty()) in.spot_at = place(spot_map_size, spot_map_size, gs::mem::psm::PSMCT32);
  in.diffuse_at = place(direct.diffuse->width, direct.diffuse->height, gs::mem::psm::PSMCT32);
  palettes_page();
  if (next <= gs::mem::memory_blocks) return in;
  in = direct;  // streamed: the normal map and the diffuse texture go through the window
  next = first;
  if (!direct.sphere.empty()) in.sphere_at = place(64, 64, gs::mem::psm::PSMCT32);
  if (!direct.spot.empty()) in.spot_at = place(spot_map_size, spot_map_size, gs::mem::psm::PSMCT32);
  palettes_page();
  if (next + 32 * 4 > gs::mem::memory_blocks)
    throw texture_does_not_fit(
        "memory path: the frame buffers, palettes and sphere map leave " +
        std::to_string(gs::mem::memory_blocks / 32 - std::min(next / 32, 512u)) +
        " of the GS's 512 pages to stream the textures through (4 are needed): use a smaller --size");
  in.window_first = next / 32;
  in.diffuse_bytes = bytes_of(direct.diffuse->texels);
  return in;
}

void start_stream(gs_inputs& in, const prepared_scene& ps, const render_options& o, const scissor& area) {
  if (in.window_first == 0) return;
  const gs::bilinear_mode filter = o.bilinear ? o.model.bilinear : gs::bilinear_mode::nearest;
  in.stream =
      std::make_shared<texture_streamer>(ps, o.model, filter, area, in.window_first, gs::mem::memory_blocks / 32);
}
stream_texture normal_map_stream(const gs_inputs& in, std::size_t layer, std::size_t k, triangle_range tris) {
  static constexpr std::array<const char*, 3> component{"x component map", "y component map", "z component map"};
  // ids: 2 the diffuse texture; layer l's 8l + 1 its index map, 8l + 3 .. 8l + 5 its component maps
  const bool one = normal_map_count(in) == 1;
  return {8 * static_cast<int>(layer) + (one ? 1 : 3 + static_cast<int>(k)),
          one ? "normal map" : component.at(k),
          index_psm(*in.nm),
          in.nm->width,
          in.nm->height,
          normal_map_texels(in, layer, k),
          tris};
}
stream_texture diffuse_stream(const gs_inputs& in) {
  return {
      2,           "diffuse texture", gs::mem::psm::PSMCT32, in.diffuse->width, in.diffuse->height, in.diffuse_bytes,
      std::nullopt};
}

void add_uploads(gs::packets::packet_builder& b, const gs_inputs& in) {
  const bool resident = in.window_first == 0;
  if (resident)
    for (std::size_t l = 0; l < in.layers.size(); ++l)
      for (std::size_t k = 0; k < normal_map_count(in); ++k)
        host_transfer(b, in.nm_at[texture_index(in, l, k)], in.nm->width, in.nm->height, normal_map_texels(in, l, k));
  if (!in.sphere.empty()) host_transfer(b, in.sphere_at, 64, 64, bytes_of(in.sphere));
  if (!in.spot.empty()) host_transfer(b, in.spot_at, spot_map_size, spot_map_size, bytes_of(in.spot));
  if (resident) host_transfer(b, in.diffuse_at, in.diffuse->width, in.diffuse->height, bytes_of(in.diffuse->texels));
  for (std::size_t l = 0; l < in.layers.size(); ++l) {
    const auto all = palettes(in, l);
    for (std::size_t k = 0; k < (l == 0 ? all.size() : normal_map_palettes); ++k) {
      std::vector<std::uint32_t> image(256);
      for (unsigned p = 0; p < 256; ++p) image[p] = (*all[k])[gs::csm1_position(gs::u8::from_wrapped(p))].to_u32();
      const gs::mem::buffer at{fixed::uint<14>::from_wrapped(in.cbp[l][k]), fixed::uint<6>::from_wrapped(1),
                               gs::mem::psm::PSMCT32};
      host_transfer(b, at, 16, 16, bytes_of(image));
    }
  }
}

gs_inputs upload_inputs(gs::mem::local_memory& m, const gs_inputs& direct, std::uint32_t first, bool parallel) {
  gs_inputs in = place_inputs(direct, first);
  auto tables = [&in, &direct] {
    auto addresses = [](const gs::mem::buffer& b, int w, int h) {
      return detail::cached_table<gs::mem::texel_addresses>(b.PSM, static_cast<std::uint32_t>(b.BW.value()),
                                                            static_cast<std::uint32_t>(w),
                                                            static_cast<std::uint32_t>(h));
    };
    if (in.window_first == 0)
      for (const gs::mem::buffer& at : in.nm_at)
        in.nm_texels.push_back(addresses(at, direct.nm->width, direct.nm->height));
    if (!direct.sphere.empty()) in.sphere_texels = addresses(in.sphere_at, 64, 64);
    if (!direct.spot.empty()) in.spot_texels = addresses(in.spot_at, spot_map_size, spot_map_size);
    if (in.window_first == 0)
      in.diffuse_texels = addresses(in.diffuse_at, direct.diffuse->width, direct.diffuse->height);
  };
  std::jthread helper;  // joins when it goes out of scope, also when an upload below throws
  if (parallel)
    helper = std::jthread(tables);
  else
    tables();
  gs::packets::packet_builder b;
  add_uploads(b, in);
  interpret(m, b);
  in.memory = &m;
  for (std::size_t l = 0; l < in.layers.size(); ++l) {
    const auto all = palettes(in, l);
    for (std::size_t k = 0; k < (l == 0 ? all.size() : normal_map_palettes); ++k) {
      gs::tex0_reg t;  // the normal map's palettes as its passes load them (16 entries for PSMT4), the rest PSMT8
      t.PSM = k < normal_map_palettes ? static_cast<gs::tex_psm>(index_psm(*in.nm)) : gs::tex_psm::PSMT8;
      t.CBP = fixed::uint<14>::from_wrapped(in.cbp[l][k]);
      t.CLD = gs::u3::from_wrapped(1);
      *all[k] = gs::mem::load_clut(m, t, {}).buffer;
    }
  }
  if (helper.joinable()) helper.join();  // before `in` is returned with the helper's tables
  return in;
}

}  // namespace gsdot3::pipeline
