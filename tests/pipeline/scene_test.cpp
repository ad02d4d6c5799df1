// The default scene (at a small size): random pixels against the per-pixel formulas, the cached
// raster path against the reference path, bands against one thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include "gs_arith/gouraud.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"
#include "proofs/methods.hpp"

namespace gsdot3::pipeline {
namespace {

scene small_scene() {
  scene s = default_scene(64);
  s.width = 160;
  s.height = 140;
  return s;
}

const scene& shared_scene() {
  static const scene s = small_scene();
  return s;
}

int ch(std::uint32_t w, int k) { return static_cast<int>((w >> (8 * k)) & 0xFF); }

// The inputs one pixel sees, interpolated as the model documents it (gs::gouraud_triangle with the
// triangle's top-left pixel as reference; UV as the exact rational, floored), and the per-pixel formula in plain
// integers.
struct pixel_inputs {
  std::array<std::int32_t, 4> colour87{};  // 8.7 Gouraud r, g, b, a
  std::int32_t u16 = 0, v16 = 0;
};

// The 12.4 texel coordinate at pixel centre (x, y) under uv_plane=exact and uv_convert=floor (the
// defaults): floor of the barycentric sum Σ E_k·a_k / area, the edge functions E_k in 12.4² units.
std::int32_t exact_uv16(const std::array<gs::xy124, 3>& p, const std::array<std::int32_t, 3>& a, int x, int y) {
  auto edge = [](gs::xy124 a0, gs::xy124 b0, std::int64_t cx, std::int64_t cy) {
    return (std::int64_t{b0.x} - a0.x) * (cy - a0.y) - (std::int64_t{b0.y} - a0.y) * (cx - a0.x);
  };
  const std::int64_t px = std::int64_t{x} * 16, py = std::int64_t{y} * 16;
  std::int64_t area = edge(p[0], p[1], p[2].x, p[2].y);
  std::int64_t n = edge(p[1], p[2], px, py) * a[0] + edge(p[2], p[0], px, py) * a[1] + edge(p[0], p[1], px, py) * a[2];
  if (area < 0) area = -area, n = -n;
  const std::int64_t q = n / area - (n % area != 0 && n < 0 ? 1 : 0);
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(q, -(1 << 20), 1 << 20));
}

pixel_inputs inputs_at(const prepared_triangle& t, const std::array<gs::rgba8, 3>& c,
                       const std::array<std::array<std::int32_t, 2>, 3>& uv, int x, int y) {
  std::array<gs::gouraud_vertex, 3> gv{};
  int xr = 1 << 16, yr = 1 << 16;
  for (std::size_t k = 0; k < 3; ++k) {
    gv[k] = {t.setup.v[k].x + xy_offset_pixels * 16, t.setup.v[k].y + xy_offset_pixels * 16, c[k]};
    xr = std::min(xr, ceil_124(t.setup.v[k].x));
    yr = std::min(yr, ceil_124(t.setup.v[k].y));
  }
  const gs::gouraud_plane gp = *gs::gouraud_triangle(gv[0], gv[1], gv[2], xr + xy_offset_pixels, yr + xy_offset_pixels);
  const gs::fragment_colour f =
      gs::gouraud_colour(gp, x + xy_offset_pixels, y + xy_offset_pixels, gs::model_options{}.setup);
  pixel_inputs in;
  in.colour87 = {f.r.value(), f.g.value(), f.b.value(), f.a.value()};
  in.u16 = exact_uv16(t.setup.v, {uv[0][0], uv[1][0], uv[2][0]}, x, y);
  in.v16 = exact_uv16(t.setup.v, {uv[0][1], uv[1][1], uv[2][1]}, x, y);
  return in;
}

// MODULATE of one channel with an 8.7 colour, clamped (../shared/spec/gs-alu-facts.md: (Ct·Cf_8.7) >> 14, min 255).
int modulate(int texel, int cf87) { return std::min(255, (texel * cf87) >> 14); }

// The DPB byte by plain integers (`formula`) and through src/proofs' per-pixel composition of the
// paper's passes (`proofs`, proofs/methods.hpp; −1 where proofs has no composition: the baseline).
struct expectation {
  int formula = 0, proofs = -1;
};

expectation expected_dot(method m, const scene& s, const prepared_scene& ps, int tri, int x, int y,
                         std::size_t light = 0) {
  const prepared_triangle& t = ps.triangles[static_cast<std::size_t>(tri)];
  const auto& lv = ps.lights[light];
  std::array<gs::rgba8, 3> colour{};
  const pixel_inputs nm_in = inputs_at(t, colour, t.uv16, x, y);
  const int size = s.normals.width;
  const glm::vec3 n = s.normals.palette[s.normals.index[static_cast<std::size_t>(
      ((nm_in.v16 >> 4) & (size - 1)) * size + ((nm_in.u16 >> 4) & (size - 1)))]];
  int sum = 0, via_proofs = -1;
  const gs::model_options o{};
  auto frag = [](const pixel_inputs& in) {
    auto c = [](std::int32_t v) { return gs::gouraud_channel::from_wrapped(v); };
    return gs::fragment_colour{c(in.colour87[0]), c(in.colour87[1]), c(in.colour87[2]), c(in.colour87[3])};
  };
  switch (m) {
    case method::four_pass: {
      std::array<std::array<std::int32_t, 2>, 3> uv{};
      for (std::size_t k = 0; k < 3; ++k) {
        const light_vertex& l = lv[t.vertex[k]];
        const int sc = std::clamp(static_cast<int>(std::lround(l.fade * 128.0f)), 0, 128);
        colour[k] = {gs::u8::from_wrapped(sc), gs::u8::from_wrapped(sc), gs::u8::from_wrapped(sc),
                     gs::u8::from_wrapped(128 - sc)};
        const st c = sphere_coordinates(l.T);
        uv[k] = {static_cast<std::int32_t>(std::lround(c.s * 1024)),
                 static_cast<std::int32_t>(std::lround(c.t * 1024))};
      }
      const pixel_inputs in = inputs_at(t, colour, uv, x, y);
      const int su = std::clamp(in.u16 >> 4, 0, 63), sv = std::clamp(in.v16 >> 4, 0, 63);
      const std::uint32_t sph = sphere_map(64, 64)[static_cast<std::size_t>(sv * 64 + su)];
      std::uint32_t dpb = 0;
      for (int k = 0; k < 3; ++k) {
        const int a2 = std::min(
            255, ((ch(sph, k) * in.colour87[static_cast<std::size_t>(k)]) >> 14) + (in.colour87[3] >> 7));  // HIGHLIGHT
        const int b2 = 128 + nearest(n[k] * 127);
        sum += (((128 - a2) * b2) >> 7) + a2;
        dpb |= static_cast<std::uint32_t>(a2) << (8 * k);
      }
      for (int k = 0; k < 3; ++k)
        dpb = proofs::methods::four_pass_channel(dpb, k, gs::u8::from_wrapped(128 + nearest(n[k] * 127)), o);
      via_proofs = proofs::methods::sum_rgb(gs::rgba8::from_u32(dpb), o).value();
      break;
    }
    case method::two_pass: {
      for (std::size_t k = 0; k < 3; ++k) colour[k] = pack_tolight(lv[t.vertex[k]].T * lv[t.vertex[k]].fade, 122);
      const pixel_inputs in = inputs_at(t, colour, t.uv16, x, y);
      const two_pass_texel p = pack_two_pass(n);
      const int P[3] = {p.positive.r.value(), p.positive.g.value(), p.positive.b.value()};
      const int N[3] = {p.negative.r.value(), p.negative.g.value(), p.negative.b.value()};
      const int na = modulate(p.negative.a.value(), in.colour87[3]);
      for (int k = 0; k < 3; ++k) {
        const int L = in.colour87[static_cast<std::size_t>(k)];
        sum += ((modulate(P[k], L) - modulate(N[k], L)) & 0xFF) + na;
      }
      const gs::rgba8 dpb = proofs::methods::two_pass_pass1(p.positive, frag(in), o);
      via_proofs =
          proofs::methods::sum_rgb_plus_3a(proofs::methods::two_pass_pass2(p.negative, frag(in), dpb, o), o).value();
      break;
    }
    case method::three_pass: {
      // Two-pass's passes 1 and 2, then (128 + N − P) added per channel: no alpha, no n'_a.
      for (std::size_t k = 0; k < 3; ++k) colour[k] = pack_tolight(lv[t.vertex[k]].T * lv[t.vertex[k]].fade, 122);
      const pixel_inputs in = inputs_at(t, colour, t.uv16, x, y);
      const two_pass_texel p = pack_two_pass(n);
      const int P[3] = {p.positive.r.value(), p.positive.g.value(), p.positive.b.value()};
      const int N[3] = {p.negative.r.value(), p.negative.g.value(), p.negative.b.value()};
      for (int k = 0; k < 3; ++k) {
        const int L = in.colour87[static_cast<std::size_t>(k)];
        sum += modulate(P[k], L) - modulate(N[k], L) + 128 + N[k] - P[k];
      }
      const gs::rgba8 terms{gs::u8::from_wrapped(128 + N[0] - P[0]), gs::u8::from_wrapped(128 + N[1] - P[1]),
                            gs::u8::from_wrapped(128 + N[2] - P[2]), gs::u8::literal(0x80)};
      const gs::rgba8 dpb = proofs::methods::two_pass_pass2(
          p.negative, frag(in), proofs::methods::two_pass_pass1(p.positive, frag(in), o), o);
      via_proofs = proofs::methods::sum_rgb(proofs::methods::three_pass_pass3(terms, dpb, o), o).value();
      break;
    }
    case method::gouraud: {
      // The vertices' 128 + nearest(127·max(T_z·fade, 0)) in red, 0 in green and blue, interpolated.
      for (std::size_t k = 0; k < 3; ++k) {
        const light_vertex& l = lv[t.vertex[k]];
        colour[k] = {gs::u8::from_wrapped(128 + nearest(std::clamp(l.T.z * l.fade, 0.0f, 1.0f) * 127)), gs::u8{},
                     gs::u8{}, gs::u8::literal(0x80)};
      }
      const pixel_inputs in = inputs_at(t, colour, t.uv16, x, y);
      sum = (in.colour87[0] >> 7) + (in.colour87[1] >> 7) + (in.colour87[2] >> 7);
      break;
    }
    case method::baseline: {
      std::array<gs::rgba8, 3> pos{}, neg{};
      for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3 T = lv[t.vertex[k]].T * lv[t.vertex[k]].fade;
        auto q = [](float v) { return gs::u8::from_wrapped(nearest(std::max(v, 0.0f) * 127)); };
        pos[k] = {q(T.x), q(T.y), q(T.z), gs::u8::literal(0x80)};
        neg[k] = {q(-T.x), q(-T.y), q(-T.z), gs::u8::literal(0x80)};
      }
      const pixel_inputs ip = inputs_at(t, pos, t.uv16, x, y), in = inputs_at(t, neg, t.uv16, x, y);
      for (int k = 0; k < 3; ++k) {
        const int np = nearest(std::max(n[k], 0.0f) * 127), nn = nearest(std::max(-n[k], 0.0f) * 127);
        const auto K = static_cast<std::size_t>(k);
        sum += 128 + modulate(np, ip.colour87[K]) + modulate(nn, in.colour87[K]) - modulate(nn, ip.colour87[K]) -
               modulate(np, in.colour87[K]);
      }
      break;
    }
  }
  return {sum & 0xFF, via_proofs};
}

class EveryMethod : public ::testing::TestWithParam<method> {};

TEST_P(EveryMethod, RandomPixelsMatchThePerPixelFormula) {
  const scene& s = shared_scene();
  const prepared_scene ps = prepare(s);
  const frame f = render(s, ps, GetParam(), {});
  std::vector<std::size_t> covered;
  for (std::size_t i = 0; i < f.visible_triangle.size(); ++i)
    if (f.visible_triangle[i] >= 0) covered.push_back(i);
  ASSERT_GT(covered.size(), 3000u);
  std::mt19937 rng(17);
  std::shuffle(covered.begin(), covered.end(), rng);
  covered.resize(2000);
  for (std::size_t i : covered) {
    const int x = static_cast<int>(i) % s.width, y = static_cast<int>(i) / s.width;
    const expectation e = expected_dot(GetParam(), s, ps, f.visible_triangle[i], x, y);
    ASSERT_EQ(f.dot[0][i], e.formula) << name(GetParam()) << " pixel " << x << "," << y << " got 0x" << std::hex
                                      << int{f.dot[0][i]} << " expected 0x" << e.formula;
    if (e.proofs >= 0) {
      ASSERT_EQ(f.dot[0][i], e.proofs) << name(GetParam()) << " pixel " << x << "," << y << " got 0x" << std::hex
                                       << int{f.dot[0][i]} << " proofs::methods gives 0x" << e.proofs;
    }
  }
}

// Section 3.8's level of detail (lod.hpp): at share 0.7 every light is a per-pixel light and a Gouraud
// light at the same place. Each light's post-filter byte is its own method's per-pixel formula (the
// frame's method for the per-pixel half, gouraud's for the other) and the unsplit frames' byte for
// that position (a dot product does not depend on the light's colour); share 1 gives the method's
// frame and share 0 Gouraud's, bit for bit.
TEST_P(EveryMethod, LevelOfDetailPairsFollowTheirMethods) {
  const scene& s = shared_scene();
  const frame plain = render(s, prepare(s), GetParam(), {}), gouraud = render(s, prepare(s), method::gouraud, {});
  scene lod = s;
  lod.lights = split_for_lod(s.lights, 0.7);
  ASSERT_EQ(lod.lights.size(), 2 * s.lights.size());
  const prepared_scene ps = prepare(lod);
  const frame f = render(lod, ps, GetParam(), {});
  for (std::size_t j = 0; j < lod.lights.size(); ++j) {
    EXPECT_EQ(lod.lights[j].gouraud, j % 2 == 1);
    EXPECT_EQ(f.dot[j], (lod.lights[j].gouraud ? gouraud : plain).dot[j / 2]) << "light " << j;
  }
  std::mt19937 rng(29);
  int seen = 0;
  for (int k = 0; k < 100000 && seen < 500; ++k) {
    const auto i = static_cast<std::size_t>(rng() % f.visible_triangle.size());
    if (f.visible_triangle[i] < 0) continue;
    ++seen;
    const int x = static_cast<int>(i) % s.width, y = static_cast<int>(i) / s.width;
    for (std::size_t j = 0; j < lod.lights.size(); ++j)
      ASSERT_EQ(f.dot[j][i],
                expected_dot(light_method(GetParam(), lod.lights[j]), lod, ps, f.visible_triangle[i], x, y, j).formula)
          << "light " << j << " pixel " << x << "," << y;
  }
  EXPECT_EQ(seen, 500);
  for (const auto& [share, expected] : {std::pair{1.0, &plain}, std::pair{0.0, &gouraud}}) {
    scene one = s;
    one.lights = split_for_lod(s.lights, share);
    EXPECT_EQ(render(one, prepare(one), GetParam(), {}).colour, expected->colour) << "share " << share;
  }
}

TEST_P(EveryMethod, CachedPathAndBandsEqualTheReferencePath) {
  const scene& s = shared_scene();
  for (float yaw : {0.0f, 180.0f, 63.0f}) {
    const prepared_scene ps = prepare(s, yaw);
    render_options ref;
    ref.path = raster_path::reference;
    ref.threads = 1;
    render_options fast;
    fast.threads = 3;
    for (bool bilinear : {false, true}) {
      ref.bilinear = fast.bilinear = bilinear;
      const frame a = render(s, ps, GetParam(), ref), b = render(s, ps, GetParam(), fast);
      ASSERT_EQ(a.colour, b.colour) << "yaw " << yaw;
      ASSERT_EQ(a.dot, b.dot) << "yaw " << yaw;
      ASSERT_EQ(a.visible_triangle, b.visible_triangle) << "yaw " << yaw;
    }
  }
}

// Random scenes: lights, camera, s, filter, thread count; the cached path and bands against the
// reference path, bit for bit.
TEST_P(EveryMethod, CachedPathEqualsReferencePathOnRandomScenes) {
  std::mt19937 rng(23 + static_cast<unsigned>(GetParam()));
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), yaw(0.0f, 360.0f);
  std::uniform_int_distribution<int> byte(0, 255), scale(60, 127), threads(2, 5), size(40, 120);
  for (int trial = 0; trial < 6; ++trial) {
    scene s = shared_scene();
    s.width = size(rng);
    s.height = size(rng);
    s.lights = {{{pos(rng), pos(rng), pos(rng)},
                 {static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                  static_cast<std::uint8_t>(byte(rng))}},
                {{pos(rng), pos(rng), pos(rng)},
                 {static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                  static_cast<std::uint8_t>(byte(rng))}}};
    s.view.eye = glm::vec3(pos(rng), pos(rng), 3.0f + std::fabs(pos(rng)));
    const prepared_scene ps = prepare(s, yaw(rng), trial % 3 == 2);
    render_options ref;
    ref.path = raster_path::reference;
    ref.threads = 1;
    ref.s = scale(rng);
    ref.bilinear = trial % 2 == 1;
    render_options fast = ref;
    fast.path = raster_path::cached;
    fast.threads = threads(rng);
    const frame a = render(s, ps, GetParam(), ref), b = render(s, ps, GetParam(), fast);
    ASSERT_EQ(a.colour, b.colour) << "trial " << trial;
    ASSERT_EQ(a.dot, b.dot) << "trial " << trial;
    ASSERT_EQ(a.pixel_ops, b.pixel_ops) << "trial " << trial;
    ASSERT_GT(
        std::count_if(a.visible_triangle.begin(), a.visible_triangle.end(), [](std::int32_t t) { return t >= 0; }), 200)
        << "trial " << trial << ": the head should be in view";
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod, ::testing::ValuesIn(gs_methods), method_param_name);

// The reference's dot products are in range and the head-on float value is 128.
TEST(Reference, CoversTheSamePixelsAndStaysInRange) {
  const scene& s = shared_scene();
  const prepared_scene ps = prepare(s);
  const frame f = render(s, ps, method::four_pass, {});
  const reference_frame r = render_reference(s, ps, f.visible_triangle, false);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < f.visible_triangle.size(); ++i) {
    ASSERT_EQ(std::isnan(r.renormalised[0][i]), f.visible_triangle[i] < 0);
    if (f.visible_triangle[i] < 0) continue;
    ++covered;
    ASSERT_LE(std::fabs(r.renormalised[0][i]), 128.001f);
    ASSERT_LE(std::fabs(r.unnormalised[0][i]), 128.001f);
  }
  EXPECT_GT(covered, 3000u);
}

// Section 3.6: fade_att "will make sure triangles facing away from the light remain unlit". Every
// four-pass pixel of a triangle whose three vertices have fade 0 for a light (n·l ≤ 0 at each) reads
// dot product 0 exactly — the sphere pass's vertex colour makes the vector 128 at every pixel, so
// each signed multiply gives 0 — for any normal-map texel and with either filter. (Its ILP entry, 1,
// still adds 1/128 of the light: ilp.dpb-clear-zero.) The domain: every such pixel of the embedded
// scene lit from four directions.
TEST(FourPass, TrianglesFacingAwayFromTheLightGetDotZero) {
  std::size_t away = 0;
  for (const glm::vec3 at : {glm::vec3{3, 0, 1}, glm::vec3{-3, 1, 1}, glm::vec3{0, 3, 0.5f}, glm::vec3{0, -3, 1}})
    for (const bool bilinear : {false, true}) {
      scene s = shared_scene();
      s.lights = {{at, {0x80, 0x80, 0x80}}};
      const prepared_scene ps = prepare(s);
      render_options o;
      o.bilinear = bilinear;
      const frame f = render(s, ps, method::four_pass, o);
      for (std::size_t i = 0; i < f.visible_triangle.size(); ++i) {
        if (f.visible_triangle[i] < 0) continue;
        const prepared_triangle& t = ps.triangles[static_cast<std::size_t>(f.visible_triangle[i])];
        if (std::all_of(t.vertex.begin(), t.vertex.end(),
                        [&](std::uint32_t v) { return ps.lights[0][v].fade == 0.0f; })) {
          ++away;
          ASSERT_EQ(f.dot[0][i], 0x80) << "pixel " << i << " light at " << at.x << "," << at.y << "," << at.z;
        }
      }
    }
  EXPECT_GT(away, 5000u);
}

// A directional light is the limit of a point light moved away along its direction: the per-vertex
// tolight vectors and fades of directional d equal those of a point light at 10^5·d (within float
// error), under a yaw too, and unlike a nearby point light's they do not depend on the vertex.
TEST(Prepare, DirectionalLightIsThePointLightAtInfinity) {
  scene far = shared_scene(), dir = far, near = far;
  const glm::vec3 d = glm::normalize(glm::vec3(-1.0f, 0.6f, 1.0f));
  far.lights = {{d * 1.0e5f, {0x80, 0x80, 0x80}}};
  dir.lights = {{d * 3.0f, {0x80, 0x80, 0x80}, light_kind::directional}};  // any length
  near.lights = {{d * 3.0f, {0x80, 0x80, 0x80}}};
  for (const float yaw : {0.0f, 90.0f}) {
    const prepared_scene pf = prepare(far, yaw), pd = prepare(dir, yaw), pn = prepare(near, yaw);
    ASSERT_EQ(pd.lights[0].size(), pf.lights[0].size());
    float worst_far = 0.0f, worst_near = 0.0f;
    for (std::size_t i = 0; i < pd.lights[0].size(); ++i) {
      worst_far = std::max({worst_far, glm::length(pd.lights[0][i].T - pf.lights[0][i].T),
                            std::fabs(pd.lights[0][i].fade - pf.lights[0][i].fade)});
      worst_near = std::max(worst_near, glm::length(pd.lights[0][i].T - pn.lights[0][i].T));
    }
    EXPECT_LT(worst_far, 1.0e-3f) << "yaw " << yaw;
    EXPECT_GT(worst_near, 0.05f) << "yaw " << yaw;  // a point light at 3·d is not the same light
  }
}

}  // namespace
}  // namespace gsdot3::pipeline
