// pipeline_unit: a frame does not depend on what the kept buffers (scratch.hpp) hold. scratch hands a
// vector back as it was given, so that the value path's frame and Z buffers are not zeroed twice; a frame
// must then set every word it reads (the bands zero their rows, the frame program clears). Every GS
// method, on the value path (1 and 3 threads, SIMD and --scalar) and on the memory path, at an odd size:
// the frame drawn after the kept buffers were filled with zeros equals the frame drawn after they were
// filled with 0xA5A5A5A5, word for word (colour, DPB bytes, visible and plain triangles, pixel-ops).
// Checked to fail with both the bands' zeroing and the program's frame clears dropped.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "method_param.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scratch.hpp"

namespace gsdot3::pipeline {
namespace {

// Takes eight kept vectors at once (more than a frame keeps), sizes from a band's row to the whole local
// memory, and gives them back holding `v` in every word.
void fill_kept_buffers(std::size_t pixels, std::uint32_t v) {
  std::array<std::unique_ptr<detail::scratch<std::uint32_t>>, 8> held;
  const std::array<std::size_t, 8> need{4 * pixels, pixels, pixels, std::size_t{1} << 20, 3 * 97, 97, 4 * pixels, 16};
  for (std::size_t i = 0; i < held.size(); ++i) {
    held[i] = std::make_unique<detail::scratch<std::uint32_t>>(need[i]);
    (*held[i])->assign(std::max((*held[i])->capacity(), need[i]), v);
  }
}

class KeptBuffers : public ::testing::TestWithParam<method> {};

TEST_P(KeptBuffers, FramesDoNotDependOnWhatTheyHold) {
  scene s = default_scene();
  s.width = 97, s.height = 61;
  const prepared_scene ps = prepare(s);
  int frames = 0;
  for (int variant = 0; variant < 4; ++variant) {
    render_options o;
    o.threads = variant == 1 ? 3 : 1;
    o.simd = variant != 2;
    o.memory_path = variant == 3;
    const std::string what = std::string(name(GetParam())) + ", variant " + std::to_string(variant);
    fill_kept_buffers(97 * 61, 0);
    const frame clean = render(s, ps, GetParam(), o);
    fill_kept_buffers(97 * 61, 0xA5A5A5A5u);
    const frame dirty = render(s, ps, GetParam(), o);
    EXPECT_EQ(clean.colour, dirty.colour) << what;
    EXPECT_EQ(clean.dot, dirty.dot) << what;
    EXPECT_EQ(clean.visible_triangle, dirty.visible_triangle) << what;
    EXPECT_EQ(clean.plain_triangle, dirty.plain_triangle) << what;
    EXPECT_EQ(clean.pixel_ops, dirty.pixel_ops) << what;
    ++frames;
  }
  EXPECT_EQ(frames, 4);
}

INSTANTIATE_TEST_SUITE_P(Methods, KeptBuffers, ::testing::ValuesIn(gs_methods), method_param_name);

}  // namespace
}  // namespace gsdot3::pipeline
