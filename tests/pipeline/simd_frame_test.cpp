// Whole frames through the SIMD pixel pipeline (render_options::simd, gs_simd; with and without the
// span engine, render_options::span_engine) equal the frames of the scalar gs::pixel_pipeline
// (--scalar) bit for bit: every method × rasteriser path × storage (value
// level, memory path, both z-trick DPB clears) × filter × specular, under every value of the model
// options the passes' units read (tfx_rounding, gouraud_fraction, blend_shift, uv_convert, uv_plane; gouraud_setup:
// plane_steps, per_pixel_floor, per_pixel), on the embedded scene at 160×140 and at 1 and 3 threads.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/default_scene.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"

namespace gsdot3::pipeline {
namespace {

struct storage {
  const char* name;
  bool memory_path;
  dpb_clear_mode clear;
};
constexpr storage storages[] = {{"value", false, dpb_clear_mode::explicit_clear},
                                {"memory", true, dpb_clear_mode::explicit_clear},
                                {"z-trick", true, dpb_clear_mode::z_trick},
                                {"z-trick-psmz32", true, dpb_clear_mode::z_trick_psmz32}};

class SimdFrame : public ::testing::TestWithParam<method> {};

TEST_P(SimdFrame, EqualsTheScalarFrameUnderEveryPathStorageAndOption) {
  static const scene s = [] {
    scene sc = default_scene(64);
    sc.width = 160, sc.height = 140;
    return sc;
  }();
  const prepared_scene ps = prepare(s);
  int frames = 0;
  long covered = 0;
  for (const raster_path path : {raster_path::cached, raster_path::reference})
    for (const storage& st : storages)
      for (int variant = 0; variant < 16; ++variant) {
        render_options o;
        o.path = path;
        o.memory_path = st.memory_path;
        o.dpb_clear = st.clear;
        o.model.tfx = variant & 1 ? gs::tfx_rounding::truncate : gs::tfx_rounding::floor;
        o.model.gouraud = variant & 2 ? gs::gouraud_fraction::truncate_to_8 : gs::gouraud_fraction::keep_fraction;
        // gouraud_setup: plane_steps, or (variant & 4) the exact plane, floored (the default; cached raster path)
        // or its distance from vertex 0 truncated (reference raster path)
        const gs::gouraud_setup exact =
            path == raster_path::cached ? gs::gouraud_setup::per_pixel_floor : gs::gouraud_setup::per_pixel;
        o.model.setup = variant & 4 ? exact : gs::gouraud_setup::plane_steps;
        o.model.shift = variant & 8 ? gs::blend_shift::truncate : gs::blend_shift::floor;
        // bit 0 of the variant's Gray code: floor_1_64 in half the variants, spread over the other options
        o.model.uv_convert =
            ((variant ^ (variant >> 1)) & 1) != 0 ? gs::uv_convert_mode::floor_1_64 : gs::uv_convert_mode::floor;
        // bit 1 of the Gray code: the fixed_16 UV plane in half the variants, every pair with uv_convert
        o.model.uv_plane =
            ((variant ^ (variant >> 1)) & 2) != 0 ? gs::uv_plane_mode::fixed_16 : gs::uv_plane_mode::exact;
        o.bilinear = variant % 3 == 1;
        o.specular = variant % 5 == 2;
        o.specular_power = o.specular ? 8.0 : 1.0;
        o.threads = variant % 2 == 0 ? 1 : 3;
        o.simd = false;
        const frame scalar = render(s, ps, GetParam(), o);
        o.simd = true;
        const frame vector = render(s, ps, GetParam(), o);
        o.span_engine = false;  // the units alone, every pixel walked by gs::attribute_walker
        const frame batched = render(s, ps, GetParam(), o);
        EXPECT_EQ(batched.colour, vector.colour) << "the span engine against the walked batches";
        const std::string what = std::string(name(GetParam())) + ", " +
                                 (path == raster_path::cached ? "cached" : "reference") + ", " + st.name +
                                 ", variant " + std::to_string(variant);
        long differing = 0;
        for (std::size_t i = 0; i < scalar.colour.size(); ++i)
          if (scalar.colour[i] != vector.colour[i] && differing++ < 3)
            ADD_FAILURE() << what << ": pixel (" << i % 160 << ", " << i / 160 << ") scalar 0x" << std::hex
                          << scalar.colour[i] << ", SIMD 0x" << vector.colour[i];
        EXPECT_EQ(differing, 0) << what;
        EXPECT_EQ(scalar.dot, vector.dot) << what;
        EXPECT_EQ(scalar.pixel_ops, vector.pixel_ops) << what;
        EXPECT_EQ(scalar.visible_triangle, vector.visible_triangle) << what;  // step 1's, in lanes or not
        for (std::int32_t t : scalar.visible_triangle) covered += t >= 0;
        ++frames;
      }
  EXPECT_EQ(frames, 2 * 4 * 16);
  EXPECT_GT(covered, 2 * 4 * 16 * 2000L) << "the head should be in view";
}

INSTANTIATE_TEST_SUITE_P(Methods, SimdFrame, ::testing::ValuesIn(gs_methods), method_param_name);

}  // namespace
}  // namespace gsdot3::pipeline
