// fuzz/render_small.cpp — libFuzzer harness: a tiny random scene (a few triangles, a small frame, a
// random normal map, lights (sometimes a spot light, in four-pass at either placement), sometimes step 5's floor, model
// options and method) through pipeline::render. No crash, and the two rasteriser paths — reference (every pass
// rasterises again) and cached (the fast path: the fragments of step 1 replayed) — give identical frames, bit for bit.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>
#include <glm/geometric.hpp>

#include "fuzz_check.hpp"
#include "pipeline/files.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scene.hpp"

namespace {

using gsdot3::fuzz::require;
namespace pl = gsdot3::pipeline;

float coordinate(FuzzedDataProvider& in, float range) { return in.ConsumeFloatingPointInRange<float>(-range, range); }
glm::vec3 point(FuzzedDataProvider& in, float range) {
  return {coordinate(in, range), coordinate(in, range), coordinate(in, range)};
}
glm::vec3 unit_vector(FuzzedDataProvider& in) {
  const glm::vec3 v = point(in, 1.0f);
  const float len = glm::length(v);
  return len > 1e-3f ? v / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

pl::scene random_scene(FuzzedDataProvider& in) {
  pl::scene s;
  s.width = in.ConsumeIntegralInRange<int>(1, 48);
  s.height = in.ConsumeIntegralInRange<int>(1, 48);
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
  const int size = 8 << in.ConsumeIntegralInRange<int>(0, 1);
  s.normals.width = s.normals.height = size;
  const int palette = in.ConsumeIntegralInRange<int>(1, 16);
  for (int i = 0; i < palette; ++i) s.normals.palette.push_back(unit_vector(in));
  for (int i = 0; i < size * size; ++i)
    s.normals.index.push_back(in.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(palette - 1)));
  s.diffuse.width = s.diffuse.height = 8;
  for (int i = 0; i < 64; ++i)
    s.diffuse.texels.push_back(0x80000000u | (in.ConsumeIntegral<std::uint32_t>() & 0xFFFFFFu));
  const int lights = in.ConsumeIntegralInRange<int>(1, 2);
  for (int i = 0; i < lights; ++i) {
    s.lights.push_back(
        {point(in, 4.0f),
         {in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>()}});
  }
  s.ambient = {in.ConsumeIntegral<std::uint8_t>(), in.ConsumeIntegral<std::uint8_t>(),
               in.ConsumeIntegral<std::uint8_t>()};
  s.view.eye = {coordinate(in, 1.0f), coordinate(in, 1.0f), in.ConsumeFloatingPointInRange<float>(2.0f, 5.0f)};
  s.view.fov_y_degrees = in.ConsumeFloatingPointInRange<float>(20.0f, 90.0f);
  return s;
}

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
  o.threads = 1;
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  pl::scene s = random_scene(in);
  try {
    pl::compute_tangents(s.model);  // throws std::runtime_error for a degenerate triangle
    pl::validate(s.model);
  } catch (const std::runtime_error&) { return 0; }
  const pl::method m = pl::gs_methods[in.ConsumeIntegralInRange<std::size_t>(0, std::size(pl::gs_methods) - 1)];
  if (in.ConsumeBool()) {  // section 3.6's spot light
    s.lights[0].kind = pl::light_kind::spot;
    s.lights[0].direction = unit_vector(in);
    s.lights[0].cone_degrees = in.ConsumeFloatingPointInRange<float>(1.0f, 80.0f);
  }
  pl::render_options o = random_options(in);
  o.spot_after_first_pass = m == pl::method::four_pass && in.ConsumeBool();
  const float yaw = in.ConsumeFloatingPointInRange<float>(0.0f, 360.0f);
  if (in.ConsumeBool()) s.plain = pl::floor_under(s.model, in.ConsumeIntegralInRange<int>(1, 4));  // step 5
  const pl::prepared_scene ps = pl::prepare(s, yaw, o.specular);
  o.path = pl::raster_path::reference;
  const pl::frame reference = pl::render(s, ps, m, o);
  o.path = pl::raster_path::cached;
  const pl::frame cached = pl::render(s, ps, m, o);
  require(reference.colour == cached.colour && reference.dot == cached.dot &&
              reference.visible_triangle == cached.visible_triangle &&
              reference.plain_triangle == cached.plain_triangle,
          [&] {
            std::size_t i = 0;
            while (i < reference.colour.size() && i < cached.colour.size() && reference.colour[i] == cached.colour[i])
              ++i;
            return "render: reference and cached paths differ (method " + std::string(pl::name(m)) + ", " +
                   std::to_string(s.width) + "x" + std::to_string(s.height) + ", first colour difference at pixel " +
                   std::to_string(i) + ")";
          });
  // The memory path (frame buffers in the modelled GS local memory) against the value level.
  o.memory_path = true;
  const pl::frame memory = pl::render(s, ps, m, o);
  require(memory.colour == cached.colour && memory.dot == cached.dot && memory.plain_triangle == cached.plain_triangle,
          [&] {
            return "render: memory path and value level differ (method " + std::string(pl::name(m)) + ", " +
                   std::to_string(s.width) + "x" + std::to_string(s.height) + ")";
          });
  return 0;
}
