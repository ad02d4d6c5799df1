// The interpreter draws what the renderer draws: random Gouraud-shaded, bilinear-textured, blended
// triangles drawn once by the renderer's own triangle pass (pipeline/band_renderer.hpp draw<Pass>, the
// attributes() set-up, the reference raster path) and once from GIF packets (XYOFFSET 2048 px as
// the renderer assumes, the texture uploaded with an IMAGE transfer) must give the same frame words.
// The expectation is the renderer's frame, an implementation that does not go through the packet
// interpreter (they share only the lower units both are built on: rasteriser, attribute set-up,
// pixel pipeline).
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "gs_packets/builder.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/band_renderer.hpp"

namespace {

namespace pl = gsdot3::pipeline;
namespace mem = gs::mem;
using namespace gs::packets;

// MODULATE with the texture's alpha, blended (Cs − Cd)·As + Cd, COLCLAMP on.
constexpr gs::alpha_reg blend{gs::blend_colour::Cs, gs::blend_colour::Cd, gs::blend_alpha::As, gs::blend_colour::Cd,
                              gs::u8{}};
constexpr pl::pass_regs textured_blend{true, true, gs::tfx::MODULATE, gs::tcc::RGBA, blend, true, 0};

// Under each gouraud_setup, uv_convert and uv_plane (both sides take them from their options).
void expect_the_renderers_frame(gs::gouraud_setup setup, gs::uv_convert_mode uv_convert = gs::uv_convert_mode::floor,
                                gs::uv_plane_mode uv_plane = gs::uv_plane_mode::exact) {
  constexpr int W = 64, H = 64, T = 16;
  std::mt19937 rng(15);
  std::uniform_int_distribution<int> xy(-8 * 16, 72 * 16), uv(0, 40 * 16), byte(0, 255);
  std::vector<std::uint32_t> texels(T * T);
  for (auto& t : texels) t = static_cast<std::uint32_t>(rng());
  std::vector<gs::rgba8> colours;
  pl::prepared_scene ps;
  ps.width = W;
  ps.height = H;
  for (int k = 0; k < 12; ++k) {
    pl::prepared_triangle t;
    std::array<pl::xy124, 3> p{};
    for (std::uint32_t i = 0; i < 3; ++i) {
      p[i] = {xy(rng), xy(rng)};
      t.uv16[i] = {uv(rng), uv(rng)};
      t.vertex[i] = static_cast<std::uint32_t>(colours.size());
      colours.push_back(gs::rgba8::from_u32(static_cast<std::uint32_t>(rng())));
    }
    t.setup = pl::setup_triangle(p);
    if (t.setup.area2 == 0) continue;
    t.z = pl::make_plane(p, {1000, 1000, 1000}, 0, 0xFFFFFF);
    ps.triangles.push_back(t);
  }
  // The renderer: frame words start at 0x40808080 (a blend destination), Z all 0 (every Z 1000 passes GEQUAL).
  pl::render_options o;
  o.path = pl::raster_path::reference;
  o.model.setup = setup;
  o.model.uv_convert = uv_convert;
  o.model.uv_plane = uv_plane;
  std::vector<std::uint32_t> z(W * H, 0), frame(W * H, 0x40808080u);
  std::vector<std::int32_t> visible(W * H, -1);
  pl::detail::band_renderer r(ps, o, pl::scissor{0, 0, W, H},
                              pl::detail::z_view{pl::detail::row_view{z.data(), W}, {}, false}, visible);
  const pl::texture_ref tex{T, T, nullptr, nullptr, texels.data(), false, o.model.bilinear, nullptr, {}};
  const auto attr = pl::detail::attributes(
      ps, o.model, [&](std::uint32_t v) { return colours[v]; },
      [](const pl::prepared_triangle& t, int k) {
        return std::pair<std::int32_t, std::int32_t>{t.uv16[static_cast<std::size_t>(k)][0],
                                                     t.uv16[static_cast<std::size_t>(k)][1]};
      });
  r.draw<textured_blend>(&tex, attr, pl::detail::row_view{frame.data(), W}, ps.layer(0));

  // The packets: FRAME_1 FBP 0 FBW 1; ZBUF_1 page 8 PSMZ24 ZMSK (the renderer's Z buffer); TEST ZTE GEQUAL; XYOFFSET
  // 2048 px; SCISSOR 0..63; the texture PSMCT32 16×16 at block 1024 (TBW 1), uploaded; TEX0 TW = TH = 4, TCC RGBA, TFX
  // MODULATE; TEX1 MMAG = MMIN = LINEAR; CLAMP REPEAT; ALPHA A = Cs, B = Cd, C = As, D = Cd.
  mem::local_memory m;
  const mem::buffer fb{fixed::uint<14>::from_wrapped(0), fixed::uint<6>::from_wrapped(1), mem::psm::PSMCT32};
  for (std::uint32_t y = 0; y < H; ++y)
    for (std::uint32_t x = 0; x < W; ++x) m.write_pixel(fb, x, y, 0x40808080u);
  packet_builder pb;
  const std::vector<std::pair<std::uint8_t, std::uint64_t>> upload{
      {0x50, std::uint64_t{1024} << 32 | std::uint64_t{1} << 48},
      {0x51, 0},
      {0x52, T | std::uint64_t{T} << 32},
      {0x53, 0}};
  pb.ad(upload);
  std::vector<std::uint8_t> bytes;
  for (const std::uint32_t t : texels)
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<std::uint8_t>(t >> (8 * b)));
  pb.image(bytes);
  const std::uint64_t tex0 = 1024 | std::uint64_t{1} << 14 | std::uint64_t{4} << 26 | std::uint64_t{4} << 30 |
                             std::uint64_t{1} << 34;  // TFX MODULATE = 0
  std::vector<std::pair<std::uint8_t, std::uint64_t>> w{
      {0x1A, 1},
      {0x46, 1},
      {0x4C, std::uint64_t{1} << 16},
      {0x4E, 8 | 1 << 24 | std::uint64_t{1} << 32},
      {0x47, 1 << 16 | 2 << 17},
      {0x18, std::uint64_t{2048 * 16} | std::uint64_t{2048 * 16} << 32},
      {0x40, 63 << 16 | std::uint64_t{63} << 48},
      {0x06, tex0},
      {0x14, 1 << 5 | 1 << 6},
      {0x08, 0},
      {0x42, 0 | 1 << 2 | 0 << 4 | 1 << 6},
      {0x00, 3 | 1 << 3 | 1 << 4 | 1 << 6 | 1 << 8}};
  for (const auto& t : ps.triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const gs::rgba8 c = colours[t.vertex[k]];
      w.push_back({0x01, c.to_u32() | std::uint64_t{0x3F800000} << 32});
      w.push_back({0x03, static_cast<std::uint64_t>(t.uv16[k][0]) | static_cast<std::uint64_t>(t.uv16[k][1]) << 16});
      w.push_back({0x05, static_cast<std::uint64_t>(t.setup.v[k].x + 2048 * 16) |
                             static_cast<std::uint64_t>(t.setup.v[k].y + 2048 * 16) << 16 | std::uint64_t{1000} << 32});
    }
  pb.ad(w, true);
  interpreter it(m, interpreter_options{o.model});
  const auto stream = pb.bytes();
  for (const gif_event& e : decode_gif(stream)) it.apply(e, 16u * e.offset);
  ASSERT_TRUE(it.unmodelled_features().empty()) << it.unmodelled_features()[0].what;
  ASSERT_EQ(it.primitives_drawn(), ps.triangles.size());
  EXPECT_EQ(it.pixels_drawn(), r.pixel_ops());
  EXPECT_GT(r.pixel_ops(), 1000u);
  for (std::uint32_t y = 0; y < H; ++y)
    for (std::uint32_t x = 0; x < W; ++x) ASSERT_EQ(m.read_pixel(fb, x, y), frame[y * W + x]) << x << "," << y;
}

TEST(RendererMatch, RandomTexturedGouraudTrianglesGiveTheRenderersFrame) {
  expect_the_renderers_frame(gs::gouraud_setup::plane_steps);
}
TEST(RendererMatch, RandomTexturedPerPixelGouraudTrianglesGiveTheRenderersFrame) {
  expect_the_renderers_frame(gs::gouraud_setup::per_pixel);
}
TEST(RendererMatch, RandomTexturedFlooredGouraudTrianglesGiveTheRenderersFrame) {
  expect_the_renderers_frame(gs::gouraud_setup::per_pixel_floor);
}
TEST(RendererMatch, RandomTexturedTrianglesWithTheUvBiasGiveTheRenderersFrame) {
  expect_the_renderers_frame(gs::gouraud_setup::per_pixel, gs::uv_convert_mode::floor_1_64);
}
TEST(RendererMatch, RandomTexturedTrianglesOnTheFixed16UvPlaneGiveTheRenderersFrame) {
  expect_the_renderers_frame(gs::gouraud_setup::per_pixel_floor, gs::uv_convert_mode::floor_1_64,
                             gs::uv_plane_mode::fixed_16);
}

}  // namespace
