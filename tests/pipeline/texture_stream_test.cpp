// Streamed textures (pipeline/texture_stream.hpp, issue 26): normal maps of 1024² (and a 2048² image
// resampled to 1024²) with their 1024² diffuse textures do not fit beside the frame buffers; the
// memory path streams them in pieces and must give the value path's frame bit for bit (the value
// path reads the host arrays, no streaming: the independent reference), and the frame's dump,
// written and read back as bytes and replayed through gs_packets' interpreter, must display that
// frame. Each case also checks that the texture really streamed (more pages uploaded in one pass than
// the window holds, i.e. the pages were reused) so that a pass cannot come from a resident texture.
// (Checked to fail: with the bilinear footprint left out of the cell sets, cells_in sampling with
// nearest, the bilinear cases differ from the value path.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "common/temp_dir.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"
#include "pipeline/band_renderer.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/files.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/normal_map_image.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"
#include "replayed_frame.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

// The pages the first normal-map pass uploads, and the window's size.
std::array<std::size_t, 2> first_pass_uploads(const scene& s, const prepared_scene& ps, method m,
                                              const render_options& o) {
  gs_inputs in = place_inputs(make_inputs(s, m, o), buffer_layout_for(s.width, s.height).first_texture_block());
  if (in.window_first == 0) return {0, 0};
  start_stream(in, ps, o, detail::band_renderer::drawn_area(ps, {0, 0, s.width, s.height}));
  std::size_t pages = 0;
  for (const stream_piece& p :
       in.stream->next_pass(normal_map_stream(in, 0, 0, {0, static_cast<std::uint32_t>(ps.triangles.size())})))
    pages += p.uploads.size();
  return {pages, in.stream->window_pages()};
}

// reuse: the normal map's first pass must upload more pages than the window holds (pieces share its
// pages); else the normal map may fit the window whole (the diffuse texture, 4 MiB, never does).
void expect_streamed_frames_equal(const scene& s, method m, render_options o, bool reuse, const std::string& what) {
  const prepared_scene ps = prepare(s, 0.0f, o.specular);
  const auto [uploaded, window] = first_pass_uploads(s, ps, m, o);
  ASSERT_GT(window, 0u) << what << ": the textures should not fit beside the frame buffers";
  if (reuse) { EXPECT_GT(uploaded, window) << what << ": one pass should upload more pages than the window holds"; }
  o.memory_path = false;
  const frame value = render(s, ps, m, o);
  o.memory_path = true;
  const frame memory = render(s, ps, m, o);
  long differing = 0;
  for (std::size_t i = 0; i < value.colour.size(); ++i)
    if (value.colour[i] != memory.colour[i] && differing++ < 3)
      ADD_FAILURE() << what << ": pixel (" << i % static_cast<std::size_t>(s.width) << ", "
                    << i / static_cast<std::size_t>(s.width) << "): value path 0x" << std::hex << value.colour[i]
                    << ", memory path 0x" << memory.colour[i];
  EXPECT_EQ(differing, 0) << what;
  EXPECT_EQ(value.dot, memory.dot) << what;
  EXPECT_GT(std::count_if(value.visible_triangle.begin(), value.visible_triangle.end(),
                          [](std::int32_t t) { return t >= 0; }),
            s.width * s.height / 10)
      << what << ": the head should fill part of the frame";

  // The dump, as bytes and back, replayed: the output buffer (DISPFB1) is the value path's frame.
  const replayed_frame replayed = replay_frame(build_frame_packets(s, ps, m, o), o.model);
  for (const auto& u : replayed.unmodelled)
    ADD_FAILURE() << what << ": unmodelled at byte " << u.offset << ": " << u.what;
  long replay_differing = 0;
  for (std::size_t i = 0; i < replayed.colour.size(); ++i) {
    const std::uint32_t w = replayed.colour[i], v = value.colour[i];
    if (w != v && replay_differing++ < 3)
      ADD_FAILURE() << what << ": replay pixel (" << i % static_cast<std::size_t>(s.width) << ", "
                    << i / static_cast<std::size_t>(s.width) << "): 0x" << std::hex << w << ", value path 0x" << v;
  }
  EXPECT_EQ(replay_differing, 0) << what << ": replayed dump";
}

scene sized(scene s, int w, int h) {
  s.width = w;
  s.height = h;
  return s;
}

// The embedded scene with a 1024² normal map and diffuse texture: the 256² procedural map's indices
// (same palette) as a 4 × 4 patchwork, each 256² tile's indices offset differently, so that no two
// pages of the map hold the same texels (a page fetched from the wrong place shows). Quantising a
// 1024² map of its own would take most of this test's time.
const scene& map_1024() {
  static const scene s = [] {
    scene t = default_scene(256);
    normal_map big{1024, 1024, std::vector<std::uint8_t>(1024u * 1024u), t.normals.palette, {}, 8, {}};
    for (int y = 0; y < 1024; ++y)
      for (int x = 0; x < 1024; ++x)
        big.index[static_cast<std::size_t>(y * 1024 + x)] = static_cast<std::uint8_t>(
            t.normals.index[static_cast<std::size_t>((y % 256) * 256 + x % 256)] + 37 * (x / 256) + 101 * (y / 256));
    t.normals = std::move(big);
    t.diffuse = procedural_diffuse(1024, 1024);
    return t;
  }();
  return s;
}

TEST(TextureStream, A1024MapAtTheDefaultFrameEqualsTheValuePath) {
  expect_streamed_frames_equal(map_1024(), method::two_pass, render_options{}, true,
                               "1024², 512x448, two-pass, nearest");
}

// Two layers (two materials' maps, scene.hpp) of 1024² each: each layer's passes stream its own
// texture over its own triangles (stream_texture::triangles), each with its layer's CLUT.
TEST(TextureStream, TwoLayersOf1024StreamEachTheirOwnTexture) {
  expect_streamed_frames_equal(sized(test::two_layers(map_1024()), 320, 240), method::two_pass, render_options{}, false,
                               "two layers of 1024², 320x240, two-pass, nearest");
}

// A 1024² 4-bit map (PSMT4: pages of 128 × 128 texels, two to a byte in the transfers), patched as
// map_1024's tiles with the embedded map's 16-entry indices offset per tile, streamed beside the
// 1024² diffuse texture.
TEST(TextureStream, A1024FourBitMapEqualsTheValuePath) {
  scene s = map_1024();
  const normal_map small = with_index_bits(default_scene(256).normals, 4);
  s.normals.palette = small.palette;
  s.normals.bits = 4;
  for (int y = 0; y < 1024; ++y)
    for (int x = 0; x < 1024; ++x)
      s.normals.index[static_cast<std::size_t>(y * 1024 + x)] = static_cast<std::uint8_t>(
          (small.index[static_cast<std::size_t>((y % 256) * 256 + x % 256)] + 5 * (x / 256) + 11 * (y / 256)) & 15);
  render_options o;
  o.bilinear = true;
  expect_streamed_frames_equal(s, method::four_pass, o, false, "1024² 4-bit, 512x448, four-pass, bilinear");
}

// A 1024² 24-bit map read by four-pass: three PSMT8 component maps (section 3.6), each streamed as a
// texture of its own (stream ids 3..5) between the sphere map and the 1024² diffuse texture; the
// texels' normals are map_1024's palette entries, so the three maps differ from each other per tile.
TEST(TextureStream, A1024TwentyFourBitMapEqualsTheValuePath) {
  scene s = map_1024();
  s.normals.unquantised.resize(s.normals.index.size());
  for (std::size_t i = 0; i < s.normals.index.size(); ++i)
    s.normals.unquantised[i] = s.normals.palette[s.normals.index[i]];
  s.normals.bits = 24;
  expect_streamed_frames_equal(s, method::four_pass, render_options{}, true,
                               "1024² 24-bit, 512x448, four-pass, nearest");
}

class TextureStreamMethods : public ::testing::TestWithParam<method> {};

// Bilinear (2 × 2 footprints, across the map's wrap at the edges), a turned head, and a frame whose
// buffers leave a window of 29 pages (512x480: 4 × 120 pages + sphere map + palettes), so that pieces
// split further and take other page strides.
TEST_P(TextureStreamMethods, A1024MapBilinearInANarrowWindowEqualsTheValuePath) {
  render_options o;
  o.bilinear = true;
  scene s = sized(map_1024(), 512, 480);
  s.view.eye = glm::vec3(1.6f, 0.8f, 2.4f);
  expect_streamed_frames_equal(s, GetParam(), o, true, "1024², 512x480, bilinear, turned");
  expect_streamed_frames_equal(sized(map_1024(), 160, 120), GetParam(), render_options{}, false,
                               "1024², 160x120, nearest");
}

INSTANTIATE_TEST_SUITE_P(Methods, TextureStreamMethods, ::testing::ValuesIn(gs_methods), method_param_name);

// PCSX2's row set-up (gouraud_setup pcsx2_rows_4 / _8, the pcsx2-sw profile) starts a row's colour at
// SCISSOR's left when the triangle's edge is left of it, so a piece cut along x would change the
// Gouraud colours of the triangles it cuts: the dump of a turned head with a streamed 1024² map and
// bilinear, replayed under that profile, differed from the render in 40 of 229 376 pixels (two-pass)
// before the streamer cut only along y under those set-ups, and a row that does not fit by
// triangles. This frame needs such rows (checked below), and four-pass draws the normal map in passes
// whose piece order alternates, so the pieces over one row must keep their triangle order.
render_options pcsx2_rows(const char* setup) {
  render_options o;
  o.bilinear = true;
  EXPECT_FALSE(gs::apply_profile(o.model, "pcsx2-sw").has_value());
  EXPECT_FALSE(gs::set_option(o.model, "gouraud_setup", setup).has_value());
  return o;
}
scene turned_1024() {
  scene s = map_1024();
  s.view.eye = glm::vec3(1.6f, 0.8f, 2.4f);
  return s;
}

TEST(TextureStream, PiecesKeepPcsx2RowStarts) {
  expect_streamed_frames_equal(turned_1024(), method::two_pass, pcsx2_rows("pcsx2_rows_8"), true,
                               "pcsx2_rows_8, 1024², bilinear, turned, two-pass");
  expect_streamed_frames_equal(turned_1024(), method::four_pass, pcsx2_rows("pcsx2_rows_4"), true,
                               "pcsx2_rows_4, 1024², bilinear, turned, four-pass");
}

// The pieces of two successive passes (the second in reverse order) under pcsx2_rows_8: every piece
// spans the drawn area's width, some rows are split by triangles, and pieces over one rectangle come
// in increasing, disjoint triangle ranges in both passes.
TEST(TextureStream, Pcsx2RowPiecesAreWholeRowsInTriangleOrder) {
  const scene s = turned_1024();
  const render_options o = pcsx2_rows("pcsx2_rows_8");
  const prepared_scene ps = prepare(s, 0.0f, o.specular);
  gs_inputs in =
      place_inputs(make_inputs(s, method::two_pass, o), buffer_layout_for(s.width, s.height).first_texture_block());
  ASSERT_GT(in.window_first, 0u);
  const scissor area = detail::band_renderer::drawn_area(ps, {0, 0, s.width, s.height});
  start_stream(in, ps, o, area);
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<stream_piece> pieces =
        in.stream->next_pass(normal_map_stream(in, 0, 0, {0, static_cast<std::uint32_t>(ps.triangles.size())}));
    int split_rows = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      EXPECT_EQ(pieces[k].area.x0, area.x0);
      EXPECT_EQ(pieces[k].area.x1, area.x1);
      if (k == 0 || !(pieces[k].area == pieces[k - 1].area)) continue;
      ++split_rows;
      EXPECT_EQ(pieces[k].triangles.first, pieces[k - 1].triangles.end) << "pass " << pass << ", piece " << k;
    }
    EXPECT_GT(split_rows, 0) << "pass " << pass << ": no row split by triangles";
  }
}

// Where one triangle's row alone needs more pages than the window has (a 512x480 frame leaves 29; in
// four-pass's diffuse pass a row of the turned head crosses the 1024² diffuse texture's wrap in v
// under bilinear: 5 cells no page stride places in 29 pages), there is no cut that keeps PCSX2's row
// starts: a user error that says so, not a frame the dump would not reproduce. (Under the default
// set-up the same frame streams, cut along x: the test above with these options.)
TEST(TextureStream, Pcsx2RowThatDoesNotFitIsAUserError) {
  const scene s = sized(turned_1024(), 512, 480);
  const render_options o = [] {
    render_options r = pcsx2_rows("pcsx2_rows_8");
    r.memory_path = true;
    return r;
  }();
  const prepared_scene ps = prepare(s, 0.0f, o.specular);
  try {
    (void)render(s, ps, method::four_pass, o);
    ADD_FAILURE() << "rendered a row that does not fit";
  } catch (const texture_does_not_fit& e) {
    EXPECT_NE(std::string(e.what()).find("pcsx2_rows"), std::string::npos) << e.what();
  }
}

// A 2048² PNG normal map (generated here: a pattern of bumps) loaded as a user's file is resampled
// to 1024² (the GS's TW/TH limit) and streams like the procedural one.
TEST(TextureStream, A2048ImageResampledTo1024EqualsTheValuePath) {
  const std::filesystem::path dir = gsdot3::test::fresh_temp_dir("gsdot3-stream");
  image img{2048, 2048, 3, {}};
  img.data.resize(2048u * 2048u * 3u);
  for (int y = 0; y < 2048; ++y)
    for (int x = 0; x < 2048; ++x) {
      const double a = 0.6 * std::sin(x * 0.0276), b = 0.6 * std::cos(y * 0.0215 + x * 0.004),
                   c = std::sqrt(std::max(0.05, 1 - a * a - b * b));
      const double l = std::sqrt(a * a + b * b + c * c);
      std::uint8_t* p = &img.data[3u * static_cast<std::size_t>(y * 2048 + x)];
      p[0] = static_cast<std::uint8_t>((a / l + 1) * 127.5), p[1] = static_cast<std::uint8_t>((b / l + 1) * 127.5);
      p[2] = static_cast<std::uint8_t>((c / l + 1) * 127.5);
    }
  write_png(dir / "n.png", img);
  const loaded_normal_map nm = load_normal_map(dir / "n.png", normal_map_settings{});
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(nm.resampled);
  ASSERT_EQ(nm.map.width, 1024);
  ASSERT_EQ(nm.map.height, 1024);
  scene s = sized(default_scene(), 256, 224);
  s.normals = nm.map;
  s.diffuse = procedural_diffuse(1024, 1024);
  for (method m : {method::two_pass, method::four_pass, method::baseline})
    expect_streamed_frames_equal(s, m, render_options{}, false, "2048² resampled, 256x224, " + std::string(name(m)));
}

// Frame buffers that take all 512 pages leave nothing to stream through: a one-line error that says
// what to change (texture_does_not_fit, which the CLI reports with exit 2), not an internal error.
TEST(TextureStream, NoRoomToStreamIsAUserError) {
  const scene s = sized(map_1024(), 512, 512);
  const prepared_scene ps = prepare(s);
  render_options o;
  o.memory_path = true;
  try {
    (void)render(s, ps, method::two_pass, o);
    ADD_FAILURE() << "rendered without room for the textures";
  } catch (const texture_does_not_fit& e) {
    EXPECT_NE(std::string(e.what()).find("use a smaller --size"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)build_frame_packets(s, ps, method::two_pass, o), texture_does_not_fit);
}

}  // namespace
}  // namespace gsdot3::pipeline
