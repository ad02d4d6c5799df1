// Section 3.6's spot light (light_kind::spot): a projective texture of intensities drawn over the DPB
// with ST/Q texture coordinates, (Cd − 128)·As + 128 per channel: in four-pass after its four passes
// (or after the first, render_options::spot_after_first_pass), in the other methods on the post
// filter's sum (pass_table.hpp's spot_step).
// Expected values from outside the renderer: the same scene with the spot light replaced by a point
// light at the same place (another sequence of passes), and the spot's projective coordinates worked
// out in double from the pixel's barycentric weights. Where the texel the pixel reads is certainly a
// full one (alpha 128: the exact coordinates within radius 0.6 of the centre, every texel centre
// within a texel's half-diagonal of them inside the 0.65 plateau) the dot byte is the point light's,
// exactly ((Cd − 128)·128 >> 7 = Cd − 128); where it is certainly an empty one (beyond radius 0.95, or a
// vertex behind the light) it is 0x80, the dot product 0. Every method and placement, on the value and
// the memory path, under the default and other model options; then value path = memory path = the
// dump replayed, frame for frame; spot_after_first_pass with another method is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "pipeline/default_scene.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/pixel_walk.hpp"
#include "pipeline/render.hpp"
#include "replayed_frame.hpp"

namespace gsdot3::pipeline {
namespace {

// The embedded scene lit by one spot light aimed at the head's centre from a random place in front.
scene spot_scene(unsigned seed, float cone) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-2.0f, 2.0f);
  scene s = default_scene(32);
  const glm::vec3 at{pos(rng), pos(rng), 2.0f + std::fabs(pos(rng))};
  scene_light l{at, {0xC0, 0x90, 0x60}, light_kind::spot};
  l.direction = glm::vec3{pos(rng) * 0.2f, pos(rng) * 0.2f, 0.0f} - at;  // braces: evaluated left to right
  l.cone_degrees = cone;
  s.lights = {l};
  s.width = 192, s.height = 168;
  return s;
}

// The methods and placements: four-pass after its passes and after the first, every other method on the sum.
struct placement {
  method m;
  bool after_first_pass;
};
constexpr placement placements[] = {{method::four_pass, false},  {method::four_pass, true}, {method::two_pass, false},
                                    {method::three_pass, false}, {method::baseline, false}, {method::gouraud, false}};

TEST(SpotLight, FullTexelsGiveThePointLightsDotAndEmptyOnesZero) {
  int trial = 0;
  for (const placement& pl : placements) {
    int full = 0, empty = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const scene spot = spot_scene(seed, 6.0f + 3.0f * static_cast<float>(seed));
      scene point = spot;
      point.lights[0].kind = light_kind::point;
      const prepared_scene ps = prepare(spot), pp = prepare(point);
      for (const bool memory : {false, true}) {
        render_options o;
        o.memory_path = memory;
        o.bilinear = trial % 2 == 1;
        o.spot_after_first_pass = pl.after_first_pass;
        if (trial % 3 == 1) o.model.shift = gs::blend_shift::truncate;
        if (trial % 3 == 2) o.model.stq_convert = gs::stq_convert_mode::floor_1_64;
        ++trial;
        const frame fs = render(spot, ps, pl.m, o), fp = render(point, pp, pl.m, o);
        ASSERT_EQ(fs.visible_triangle, fp.visible_triangle);
        for_each_covered_pixel(ps, fs.visible_triangle, [&](const pixel_sample& p) {
          const prepared_triangle& t = ps.triangles[p.triangle];
          double S = 0, T = 0, Q = 0;
          bool front = true;
          for (std::size_t k = 0; k < 3; ++k) {
            const spot_vertex& v = ps.spots[0][t.vertex[k]];
            front = front && v.front;
            const double w = p.lambda[static_cast<int>(k)];
            S += v.S * w, T += v.T * w, Q += v.Q * w;
          }
          const double r = front ? std::hypot(2.0 * S / Q - 1.0, 2.0 * T / Q - 1.0) : 10.0;
          if (r < 0.6) {
            ASSERT_EQ(fs.dot[0][p.index], fp.dot[0][p.index])
                << name(pl.m) << " pixel " << p.x << "," << p.y << " r " << r;
            ++full;
          } else if (r > 0.95) {
            ASSERT_EQ(fs.dot[0][p.index], 0x80) << name(pl.m) << " pixel " << p.x << "," << p.y << " r " << r;
            ++empty;
          }
        });
      }
    }
    EXPECT_GT(full, 1000) << name(pl.m);
    EXPECT_GT(empty, 1000) << name(pl.m);
  }
}

// The dump of a spot-lit frame replayed through the packet interpreter (PRIM.FST = 0, Q per vertex) is
// the memory path's frame, which is the value path's, under the default and other STQ options.
TEST(SpotLight, ValuePathMemoryPathAndReplayedDumpAgree) {
  for (unsigned seed = 10; seed < 16; ++seed) {
    const placement pl = placements[seed - 10];
    scene s = spot_scene(seed, 12.0f);  // narrow: the partial ring crosses the head
    s.lights.push_back({{2.6f, -0.2f, 0.4f}, {0x10, 0x38, 0xB0}, light_kind::point});
    const prepared_scene ps = prepare(s);
    render_options o;
    o.spot_after_first_pass = pl.after_first_pass;
    if (seed == 11)
      o.model.stq_convert = gs::stq_convert_mode::trunc_16_16, o.model.stq_range = gs::stq_range_mode::x86_int32;
    if (seed == 12) o.bilinear = true;
    const frame value = render(s, ps, pl.m, o);
    o.memory_path = true;
    const frame memory = render(s, ps, pl.m, o);
    EXPECT_EQ(value.colour, memory.colour) << "seed " << seed;
    EXPECT_EQ(value.dot, memory.dot) << "seed " << seed;
    const replayed_frame replayed = replay_frame(build_frame_packets(s, ps, pl.m, o), o.model);
    EXPECT_TRUE(replayed.unmodelled.empty());
    EXPECT_EQ(replayed.colour, value.colour) << "seed " << seed;
  }
}

TEST(SpotLight, AfterTheFirstPassIsFourPassOnly) {
  const scene s = spot_scene(1, 20.0f);
  const prepared_scene ps = prepare(s);
  render_options o;
  o.spot_after_first_pass = true;
  for (const method m : {method::two_pass, method::baseline, method::three_pass, method::gouraud})
    EXPECT_THROW(render(s, ps, m, o), std::invalid_argument) << name(m);
}

}  // namespace
}  // namespace gsdot3::pipeline
