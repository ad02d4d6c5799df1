// fuzz/render_small.cpp — libFuzzer harness over every render option a user can set (issue 51): a
// random scene of a few triangles in a frame of 1x1 up to 320x320 (any size, not only whole pages),
// a random normal map at 4, 8 or 24 bits of one layer or two (materials' maps, the triangles' layers
// random), 1 to 6 lights, a spot light at either four-pass placement,
// step 5's floor, section 3.8's LOD fade (a share, or one derived from the camera's distance), model
// options, and the combination class below. What must hold:
// - no crash, and the only refusals (std::invalid_argument) are the documented ones: the one-buffer
//   variant with a z-trick clear or with more than 3 lights (gs_inputs.cpp's make_inputs);
// - the frame under the chosen options equals the canonical one (value path, explicit clears, two
//   buffers, SIMD units and span engine, cached rasteriser): memory path = value path, scalar (traced or not)
//   = SIMD, the walked SIMD batches (render_options::span_engine off) = the span engine, reference
//   raster path = cached, one buffer = two, z-trick clears = explicit ones (z-trick-psmz32 under a
//   texture buffer that holds the page, where section 3.4 claim (e) says it is the same frame);
// - the frame's GS dump (any DPB clear, either draw-buffer mode) replays to the same colours (frames of
//   up to 4 pages: the interpreter's replay of a larger one takes seconds under ASan).
// Input layout: the first integer FuzzedDataProvider takes (two bytes, from the end) is the combination
// class k < class_count, in mixed radix method (5) · DPB clear (3) · draw buffers (2) · memory path (2)
// · normal-map bits (3) · extra (5: none, floor, spot after the light passes, spot after four-pass's
// first pass, LOD fade); corpus/render_small/class-K is a seed of class K (render_small_seeds.py).
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>
#include <glm/geometric.hpp>

#include "fuzz_check.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/files.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scene.hpp"

namespace {

using gsdot3::fuzz::require;
namespace pl = gsdot3::pipeline;

enum class extra { none, floor, spot, spot_first_pass, lod };
struct combination {
  pl::method m;
  pl::dpb_clear_mode clear;
  pl::draw_buffers buffers;
  bool memory_path;
  int bits;
  extra e;
};
constexpr std::size_t class_count = 5 * 3 * 2 * 2 * 3 * 5;
combination decode(std::size_t k) {
  auto digit = [&](std::size_t radix) {
    const std::size_t d = k % radix;
    k /= radix;
    return d;
  };
  combination c{};
  c.m = pl::gs_methods[digit(5)];
  c.clear = static_cast<pl::dpb_clear_mode>(digit(3));
  c.buffers = digit(2) == 0 ? pl::draw_buffers::two : pl::draw_buffers::one;
  c.memory_path = digit(2) == 1;
  constexpr int bits[] = {8, 4, 24};
  c.bits = bits[digit(3)];
  c.e = static_cast<extra>(digit(5));
  return c;
}

float coordinate(FuzzedDataProvider& in, float range) { return in.ConsumeFloatingPointInRange<float>(-range, range); }
glm::vec3 point(FuzzedDataProvider& in, float range) {
  return {coordinate(in, range), coordinate(in, range), coordinate(in, range)};
}
glm::vec3 unit_vector(FuzzedDataProvider& in) {
  const glm::vec3 v = point(in, 1.0f);
  const float len = glm::length(v);
  return len > 1e-3f ? v / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

// A normal map of `size`² texels with a palette of up to 16 entries; every texel keeps an unquantised
// normal near its palette entry (what with_index_bits(.., 24) reads), one byte per component.
pl::normal_map random_normals(FuzzedDataProvider& in, int bits, int size) {
  pl::normal_map nm;
  nm.width = nm.height = size;
  const int palette = in.ConsumeIntegralInRange<int>(1, 16);
  for (int i = 0; i < palette; ++i) nm.palette.push_back(unit_vector(in));
  for (int i = 0; i < size * size; ++i) {
    nm.index.push_back(in.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(palette - 1)));
    glm::vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = static_cast<float>(in.ConsumeIntegral<std::int8_t>()) / 1280.0f;
    const glm::vec3 n = nm.palette[nm.index.back()] + d;
    nm.unquantised.push_back(glm::length(n) > 1e-3f ? glm::normalize(n) : nm.palette[nm.index.back()]);
  }
  return bits == 8 ? nm : pl::with_index_bits(nm, bits);
}

pl::scene random_scene(FuzzedDataProvider& in, const combination& c) {
  pl::scene s;
  const int most = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? 320 : 48;  // now and then past 256
  s.width = in.ConsumeIntegralInRange<int>(1, most);
  s.height = in.ConsumeIntegralInRange<int>(1, most);
  const int vertices = in.ConsumeIntegralInRange<int>(3, 9);
  for (int i = 0; i < vertices; ++i) {
    pl::vertex v;
    v.position = point(in, 1.5f);
    v.normal = unit_vector(in);
    v.uv = {in.ConsumeFloatingPointInRange<float>(-2.0f, 2.0f), in.ConsumeFloatingPointInRange<float>(-2.0f, 2.0f)};
    s.model.vertices.push_back(v);
  }
  const int triangles = in.ConsumeIntegralInRange<int>(1, 4);
  auto index = [&] { return in.ConsumeIntegralInRange<std::uint32_t>(0, static_cast<std::uint32_t>(vertices - 1)); };
  for (int t = 0; t < triangles; ++t) s.model.triangles.push_back({index(), index(), index()});
  const int lights = in.ConsumeIntegralInRange<int>(1, 6);
  for (int i = 0; i < lights; ++i) {
    const auto kind = in.ConsumeBool() ? pl::light_kind::point : pl::light_kind::directional;
    s.lights.push_back(
        {point(in, 4.0f),
         {in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>()},
         kind});
    if (kind == pl::light_kind::directional && glm::length(s.lights.back().position) < 1e-3f)
      s.lights.back().position = {0.0f, 0.0f, 1.0f};
  }
  s.ambient = {in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>(),
               in.ConsumeIntegral<std::uint8_t>()};
  s.view.eye = {coordinate(in, 1.0f), coordinate(in, 1.0f), in.ConsumeFloatingPointInRange<float>(2.0f, 5.0f)};
  s.view.fov_y_degrees = in.ConsumeFloatingPointInRange<float>(20.0f, 90.0f);
  if (c.e == extra::spot || c.e == extra::spot_first_pass) {  // section 3.6's spot light
    s.lights[0].kind = pl::light_kind::spot;
    s.lights[0].direction = unit_vector(in);
    s.lights[0].cone_degrees = in.ConsumeFloatingPointInRange<float>(1.0f, 80.0f);
  }
  if (c.e == extra::floor) s.plain = pl::floor_under(s.model, in.ConsumeIntegralInRange<int>(1, 4));  // step 5
  // The textures last: an input that runs out of bytes has every choice above made.
  const int map_size = 8 << in.ConsumeIntegralInRange<int>(0, 1);
  s.normals = random_normals(in, c.bits, map_size);
  if (in.ConsumeBool())  // a second layer (a second material's map, scene.hpp): mesh::layer chosen last
    s.normals = pl::stacked({s.normals, random_normals(in, c.bits, map_size)});
  s.diffuse.width = s.diffuse.height = 8;
  for (int i = 0; i < 64; ++i)
    s.diffuse.texels.push_back(0x80000000u | (in.ConsumeIntegral<std::uint32_t>() & 0xFFFFFFu));
  return s;
}

// A square of side 2 in z = 0 facing +z, UVs once across: what a degenerate random mesh is replaced by.
pl::mesh facing_quad() {
  pl::mesh m;
  for (const glm::vec2 p : {glm::vec2{-1, -1}, glm::vec2{1, -1}, glm::vec2{1, 1}, glm::vec2{-1, 1}})
    m.vertices.push_back({{p.x, p.y, 0.0f}, {0.0f, 0.0f, 1.0f}, {}, {}, (p + 1.0f) * 0.5f});
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  pl::compute_tangents(m);
  return m;
}

// Section 3.8: every light split into a per-pixel and a Gouraud light, at a share given or derived
// from the camera's distance by the ramp of --lod-distance (NEAR, FAR).
struct lod_choice {
  double share;
  std::optional<std::array<double, 2>> range;
};
lod_choice random_lod(FuzzedDataProvider& in) {
  lod_choice l{in.ConsumeProbability<double>(), std::nullopt};
  if (in.ConsumeBool()) {
    const double near = in.ConsumeFloatingPointInRange<double>(0.0, 6.0);
    l.range = std::array<double, 2>{near, near + in.ConsumeFloatingPointInRange<double>(1e-3, 6.0)};
  }
  return l;
}
void fade(const lod_choice& l, pl::scene& s) {
  const double share = l.range ? pl::lod_share_at(pl::camera_distance(s), (*l.range)[0], (*l.range)[1]) : l.share;
  s.lights = pl::split_for_lod(s.lights, share);
}

// The model options and the options that must not change the frame.
pl::render_options random_options(FuzzedDataProvider& in) {
  pl::render_options o;
  o.s = in.ConsumeIntegralInRange<int>(1, 127);
  o.bilinear = in.ConsumeBool();
  o.specular = in.ConsumeBool();
  o.specular_power = o.specular ? in.ConsumeFloatingPointInRange<double>(1.0, 32.0) : 1.0;
  o.model.tfx = in.ConsumeBool() ? gs::tfx_rounding::truncate : gs::tfx_rounding::floor;
  o.model.gouraud = in.ConsumeBool() ? gs::gouraud_fraction::truncate_to_8 : gs::gouraud_fraction::keep_fraction;
  o.model.shift = in.ConsumeBool() ? gs::blend_shift::truncate : gs::blend_shift::floor;
  o.model.bilinear = in.ConsumeBool() ? gs::bilinear_mode::nearest : gs::bilinear_mode::lerp16_4;
  o.model.stq_range = in.ConsumeBool() ? gs::stq_range_mode::x86_int32 : gs::stq_range_mode::saturate_2047;
  o.model.stq_convert = static_cast<gs::stq_convert_mode>(in.ConsumeIntegralInRange<int>(0, 2));
  o.model.uv_convert = in.ConsumeBool() ? gs::uv_convert_mode::floor_1_64 : gs::uv_convert_mode::floor;
  o.model.tex_buffer = static_cast<gs::texture_buffer>(in.ConsumeIntegralInRange<int>(0, 3));
  o.model.setup = static_cast<gs::gouraud_setup>(in.ConsumeIntegralInRange<int>(0, 5));  // all six Gouraud set-ups
  o.model.uv_plane = in.ConsumeBool() ? gs::uv_plane_mode::fixed_16 : gs::uv_plane_mode::exact;
  o.threads = in.ConsumeIntegralInRange<int>(1, 3);
  return o;
}

std::string describe(const combination& c, const pl::scene& s, const pl::render_options& o) {
  return std::string(pl::name(c.m)) + ", " + std::string(pl::name(c.clear)) +
         (c.buffers == pl::draw_buffers::one ? ", one buffer" : ", two buffers") +
         (c.memory_path ? ", memory path" : ", value path") +
         (o.simd ? (o.span_engine ? ", SIMD, span engine" : ", SIMD, walked") : ", scalar") +
         (o.path == pl::raster_path::reference ? ", reference raster" : "") + ", " + std::to_string(c.bits) +
         "-bit map of " + std::to_string(pl::layers(s.normals)) + " layer(s), extra " +
         std::to_string(static_cast<int>(c.e)) + ", " + std::to_string(s.lights.size()) + " lights, " +
         std::to_string(s.width) + "x" + std::to_string(s.height);
}

bool same(const pl::frame& a, const pl::frame& b) {
  return a.colour == b.colour && a.dot == b.dot && a.visible_triangle == b.visible_triangle &&
         a.plain_triangle == b.plain_triangle;
}

std::vector<std::uint32_t> replayed_colour(const pl::frame_packets& fp, const gs::model_options& model) {
  const gs::dump::gs_dump d = gs::dump::read_dump(gs::dump::write_dump(pl::frame_dump(fp)));
  gs::mem::local_memory mem;
  gs::packets::interpreter gs(mem, {model, false});
  gs.replay(d);
  require(gs.unmodelled_features().empty(), [] { return std::string("the frame's dump uses unmodelled features"); });
  const gs::mem::buffer out = fp.buffers.colour(fp.buffers.output());
  std::vector<std::uint32_t> colour;
  for (int y = 0; y < fp.height; ++y)
    for (int x = 0; x < fp.width; ++x)
      colour.push_back(mem.read_pixel(out, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) | 0xFF000000u);
  return colour;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const combination c = decode(in.ConsumeIntegral<std::uint16_t>() % class_count);
  // Every option before the scene, the scene's textures last (random_scene).
  pl::render_options canonical = random_options(in);
  const float yaw = in.ConsumeFloatingPointInRange<float>(0.0f, 360.0f);
  pl::render_options o = canonical;
  o.dpb_clear = c.clear, o.buffers = c.buffers, o.memory_path = c.memory_path;
  o.spot_after_first_pass = c.e == extra::spot_first_pass && c.m == pl::method::four_pass;
  canonical.spot_after_first_pass = o.spot_after_first_pass;
  o.simd = in.ConsumeBool();
  o.span_engine = in.ConsumeBool();    // with simd: the value path's triangle passes in the span engine
  std::vector<pl::pass_record> trace;  // as the report traces its DPB pictures (scalar, one band)
  if (!o.simd && in.ConsumeBool()) o.trace = &trace;
  o.path = in.ConsumeBool() ? pl::raster_path::reference : pl::raster_path::cached;
  const gs::texture_buffer page_held = in.ConsumeBool() ? gs::texture_buffer::page : gs::texture_buffer::draw_snapshot;
  const lod_choice lod = random_lod(in);

  pl::scene s = random_scene(in, c);
  try {
    pl::compute_tangents(s.model);  // throws std::runtime_error for a degenerate triangle
    pl::validate(s.model);
  } catch (const std::runtime_error&) {
    s.model = facing_quad();  // so that every input draws (random bytes often make a degenerate mesh)
    if (c.e == extra::floor) s.plain = pl::floor_under(s.model);
  }
  if (pl::layers(s.normals) > 1)
    for (std::size_t t = 0; t < s.model.triangles.size(); ++t) s.model.layer.push_back(in.ConsumeBool());
  if (c.e == extra::lod) fade(lod, s);
  const pl::prepared_scene ps = pl::prepare(s, yaw, canonical.specular);

  const bool refused_by_design = c.buffers == pl::draw_buffers::one && (c.clear != pl::dpb_clear_mode::explicit_clear ||
                                                                        s.lights.size() > pl::max_free_alpha_lights);
  if (c.clear == pl::dpb_clear_mode::z_trick_psmz32) {
    pl::render_options any = o;  // under any texture buffer: drawn, no crash
    if (!refused_by_design) (void)pl::render(s, ps, c.m, any);
    o.model.tex_buffer = page_held;
  }
  pl::frame f;
  try {
    f = pl::render(s, ps, c.m, o);
  } catch (const std::invalid_argument& e) {
    require(refused_by_design, [&] { return "render refused " + describe(c, s, o) + ": " + e.what(); });
    return 0;
  }
  require(!refused_by_design, [&] { return "render drew a combination the model refuses: " + describe(c, s, o); });
  for (const pl::pass_record& p : trace)
    require(p.word.size() == f.colour.size(), [&] { return "a traced pass is not frame-sized: " + p.label; });
  const pl::frame expected = pl::render(s, ps, c.m, canonical);
  require(same(f, expected), [&] {
    std::size_t i = 0;
    while (i < f.colour.size() && i < expected.colour.size() && f.colour[i] == expected.colour[i]) ++i;
    return "render: " + describe(c, s, o) + " differs from the value path's two-buffer frame with explicit clears " +
           "(first colour difference at pixel " + std::to_string(i) + ")";
  });
  // The dump writer's frames, replayed up to 4 pages: the packet interpreter sets up every channel-fetch
  // sprite (128 a page and pass) as a primitive of its own, about 1/2 s in Release at 36 pages.
  const int pages = ((s.width + 63) / 64) * ((s.height + 31) / 32);
  if (pages <= 4) {
    pl::render_options d = o;  // the frame's own options: its DPB clear, draw buffers and model options
    d.trace = nullptr;
    require(replayed_colour(pl::build_frame_packets(s, ps, c.m, d), d.model) == f.colour,
            [&] { return "the GS dump of " + describe(c, s, d) + " replays to another frame"; });
  }
  return 0;
}
