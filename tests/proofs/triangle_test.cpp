// two-pass.max-s.interpolated on whole triangles: every certificate replayed through the pipeline's
// rasteriser, its attribute set-up and gs::pixel_pipeline with the pipeline's two-pass registers,
// the wrap checked against a plain-int value; and the error bound of two_pass::triangle
// (|E_c| < 1 + a + b 8.7 units) and its per-channel statements (A)–(C) checked against the exact
// rational plane by brute force over every triangle on a coarse vertex lattice of a small window,
// and on random full-size triangles; the --brute-force loop (proofs/triangle_brute_force) checked
// against that window enumeration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "pipeline/band_renderer.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/raster.hpp"
#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/triangle_brute_force.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"
#include "reference.hpp"

namespace p = gsdot3::proofs;
namespace pl = gsdot3::pipeline;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
// The pipeline's two-pass passes 1 and 2 (pipeline/render.cpp two_pass_positive / two_pass_negative).
constexpr gs::alpha_reg subtract_source{gs::blend_colour::Cd, gs::blend_colour::Cs, gs::blend_alpha::FIX,
                                        gs::blend_colour::zero, gs::u8::literal(0x80)};
constexpr pl::pass_regs pass1{true, false, gs::tfx::MODULATE, gs::tcc::RGB, {}, false, 0};
constexpr pl::pass_regs pass2{true, true, gs::tfx::MODULATE, gs::tcc::RGBA, subtract_source, false, 0};

// The light's attributes as the pipeline's attribute set-up builds them for one triangle, under `gouraud`.
gs::triangle_attributes pipeline_attributes(const pl::triangle_setup& setup, const tt::triangle_case& c,
                                            gs::gouraud_setup gouraud) {
  pl::prepared_scene ps;
  ps.width = ps.height = 2048;
  pl::prepared_triangle tri;
  tri.vertex = {0, 1, 2};
  tri.setup = setup;
  ps.triangles.push_back(tri);
  gs::model_options model;
  model.setup = gouraud;
  const auto attr = pl::detail::attributes(
      ps, model, [&](std::uint32_t v) { return tt::light_colour(c.light[v]); },
      [](const pl::prepared_triangle&, int) {
        return std::pair<std::int32_t, std::int32_t>{0, 0};
      });
  return attr[0];
}
gs::gouraud_plane pipeline_plane(const pl::triangle_setup& setup, const tt::triangle_case& c) {
  return pipeline_attributes(setup, c, gs::gouraud_setup::plane_steps).colour;
}

// Plain-int two-pass value for an 8.7 light (floor of n·L / 2^14 per channel, pass 2 subtracted).
int plain_value(const ref::normal& n, const int L[3], bool truncate_to_8) {
  const int nc[3] = {n.x, n.y, n.z};
  int v = 3 * n.alpha - 384;
  for (int c = 0; c < 3; ++c) {
    const int l = truncate_to_8 ? (L[c] >> 7) << 7 : L[c];
    v += nc[c] >= 0 ? (nc[c] * l) >> 14 : -((-nc[c] * l) >> 14);
  }
  return v;
}

// What one product's floor or ceiling gives back at most, in levels: n_c·M_c is a whole number
// (16383/16384), a multiple of 128 under truncate_to_8 (127/128). FloorsGiveBackAtMostG checks it.
double floor_give_back(gs::gouraud_fraction g) {
  return g == gs::gouraud_fraction::truncate_to_8 ? 127.0 / 128 : 16383.0 / 16384;
}
}  // namespace

TEST(Triangle, EveryCertificateWrapsThroughTheRasteriserAndThePixelPipeline) {
  int replayed = 0;
  for (const auto& c : tt::certificates()) {
    for (const auto& l : c.light) ASSERT_TRUE(p::is_packed_light(c.s, l));
    const pl::triangle_setup setup = pl::setup_triangle(
        {pl::xy124{c.xy16[0], c.xy16[1]}, pl::xy124{c.xy16[2], c.xy16[3]}, pl::xy124{c.xy16[4], c.xy16[5]}});
    bool covered = false;
    pl::rasterise_triangle(setup, pl::scissor{0, 0, 2048, 2048},
                           [&](int x, int y) { covered = covered || (x == c.px && y == c.py); });
    ASSERT_TRUE(covered) << "s " << c.s;
    const auto plane = pipeline_plane(setup, c);
    const gs::fragment_colour cf = gs::gouraud_at(plane, c.px + pl::xy_offset_pixels, c.py + pl::xy_offset_pixels);
    ASSERT_EQ(cf, tt::pixel_light(c));
    ASSERT_EQ(gs::gouraud_exact_at(plane, c.px + pl::xy_offset_pixels, c.py + pl::xy_offset_pixels),
              tt::pixel_light(c, gs::gouraud_setup::per_pixel));
    const auto nm = p::paper::pack_normal_from(c.iX, c.iY);
    const auto pal = p::two_pass::palettes(nm);
    const ref::normal n = ref::appendix2(c.iX, c.iY);
    const int L[3] = {cf.r.value(), cf.g.value(), cf.b.value()};
    for (auto g : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
      gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
      o.gouraud = g;
      const std::uint32_t dpb1 = pl::gs_pixel(pass1.registers(), pal.pos, cf, 0x00808080u, c.px, c.py, o);
      const std::uint32_t dpb2 = pl::gs_pixel(pass2.registers(), pal.neg, cf, dpb1, c.px, c.py, o);
      const int r = dpb2 & 0xFF, gg = (dpb2 >> 8) & 0xFF, b = (dpb2 >> 16) & 0xFF, a = dpb2 >> 24;
      const int dot_byte = (r + gg + b + 3 * a - 128) & 0xFF;  // the post filter: (r+a)+(g+a)+(b+a) − 128, mod 256
      const int dot = dot_byte >= 128 ? dot_byte - 256 : dot_byte;
      const int value = plain_value(n, L, g == gs::gouraud_fraction::truncate_to_8);
      EXPECT_EQ(dot, ((value + 128) & 0xFF) - 128) << "the DPB holds the value mod 256";
      const auto model = p::two_pass::pixel(nm, cf, o);
      EXPECT_EQ(model.value, value);
      EXPECT_EQ(model.dot, dot);
      if (value >= 128 || value <= -129) ++replayed;
    }
    // Each certificate wraps under at least the options it was found for (s = 85, 86, 89, 90, 91, 98 and 100
    // have one row per gouraud_fraction, s = 84 a truncate_to_8 row only, the s = 124 row with
    // n = (24, 59, 111) per_pixel with truncate_to_8), above 127 or (those s = 84, 89 and 124 rows) below −128.
    auto wraps = [](int v) { return v >= 128 || v <= -129; };
    const auto exact = gs::gouraud_exact_at(plane, c.px + pl::xy_offset_pixels, c.py + pl::xy_offset_pixels);
    const int E[3] = {exact.r.value(), exact.g.value(), exact.b.value()};
    bool wrapped = wraps(plain_value(n, L, false)) || wraps(plain_value(n, L, true)) || wraps(plain_value(n, E, true));
    // and under PCSX2 SW's row set-ups (the pcsx2_rows rows): the pipeline's attribute set-up (SCISSOR's
    // left at window pixel 0) gives the proof's pixel_light, and the light wraps under either fraction
    for (auto s : {gs::gouraud_setup::pcsx2_rows_4, gs::gouraud_setup::pcsx2_rows_8}) {
      const auto rows = pipeline_attributes(setup, c, s).colour_at(c.px, c.py);
      ASSERT_EQ(rows, tt::pixel_light(c, s)) << "s " << c.s;
      const int R[3] = {rows.r.value(), rows.g.value(), rows.b.value()};
      wrapped = wrapped || wraps(plain_value(n, R, false)) || wraps(plain_value(n, R, true));
    }
    EXPECT_TRUE(wrapped) << "s " << c.s;
  }
  // s = 122..125 and the flat s = 126 under both options, the s = 91 and s = 89 keep_fraction rows under
  // both, every other row under its own
  EXPECT_EQ(replayed, 27);
}

namespace {
// |L_c − P_c(pixel)| < 1 + a + b for every channel, with P_c the exact plane (rational, ×det):
// P_c·det = 128·(c0·det + d1·(by·qx − bx·qy) + d2·(ax·qy − ay·qx)), q = 16·pixel − v0 (< 2^46).
// Returns the number of pixels checked.
// A 5 × 5 lattice of 12.4 points spaced 23/16 pixel, inside a 6-pixel window.
std::vector<std::array<int, 2>> small_lattice() {
  std::vector<std::array<int, 2>> pts;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) pts.push_back({3 + 23 * i, 5 + 23 * j});
  return pts;
}

long check_error_bound(const std::array<int, 6>& xy16, const std::array<p::ivec3, 3>& lights) {
  const tt::triangle_case c{100, 0, 0, lights, xy16, 0, 0};
  const auto setup =
      pl::setup_triangle({pl::xy124{xy16[0], xy16[1]}, pl::xy124{xy16[2], xy16[3]}, pl::xy124{xy16[4], xy16[5]}});
  if (setup.area2 == 0) return 0;
  const int xref = (std::min({xy16[0], xy16[2], xy16[4]}) + 15) >> 4,
            yref = (std::min({xy16[1], xy16[3], xy16[5]}) + 15) >> 4;
  const std::int64_t ax = xy16[2] - xy16[0], ay = xy16[3] - xy16[1], bx = xy16[4] - xy16[0], by = xy16[5] - xy16[1];
  const std::int64_t det = ax * by - bx * ay;
  long n = 0;
  pl::rasterise_triangle(setup, pl::scissor{0, 0, 2048, 2048}, [&](int x, int y) {
    tt::triangle_case k = c;
    k.px = x, k.py = y;
    const auto cf = tt::pixel_light(k);
    const int L[3] = {cf.r.value(), cf.g.value(), cf.b.value()};
    const std::int64_t qx = 16 * x - xy16[0], qy = 16 * y - xy16[1];
    const std::int64_t bound = 1 + (x - xref) + (y - yref);
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const std::int64_t c0 = 128 + lights[0][ch], d1 = lights[1][ch] - lights[0][ch],
                         d2 = lights[2][ch] - lights[0][ch];
      const std::int64_t Pdet = 128 * (c0 * det + d1 * (by * qx - bx * qy) + d2 * (ax * qy - ay * qx));
      const std::int64_t diff = L[ch] * det - Pdet;
      const std::int64_t ad = det < 0 ? -det : det;
      EXPECT_LT(diff < 0 ? -diff : diff, bound * ad) << x << " " << y;
    }
    ++n;
  });
  return n;
}
}  // namespace

TEST(Triangle, ErrorBoundHoldsOnEveryLatticeTriangleOfASmallWindow) {
  // Vertices on a 5 × 5 lattice of 12.4 points spaced 23/16 pixel in a 6-pixel window (every
  // triangle of three distinct points), lights from L_12 by a fixed rotation: every covered pixel.
  const auto lights = p::packed_lights(12);
  const auto pts = small_lattice();
  long pixels = 0, k = 0;
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = 0; b < pts.size(); ++b)
      for (std::size_t c = 0; c < pts.size(); ++c) {
        if (a == b || b == c || a == c) continue;
        ++k;
        const std::array<p::ivec3, 3> l{lights[(k * 7919) % lights.size()], lights[(k * 104729) % lights.size()],
                                        lights[(k * 1299709) % lights.size()]};
        pixels += check_error_bound({pts[a][0], pts[a][1], pts[b][0], pts[b][1], pts[c][0], pts[c][1]}, l);
      }
  EXPECT_GT(pixels, 10000);
}

TEST(Triangle, ErrorBoundHoldsOnRandomFullSizeTriangles) {
  std::mt19937_64 rng(13);
  const auto lights = p::packed_lights(122);
  std::uniform_int_distribution<int> coord(0, 2047 * 16), light(0, static_cast<int>(lights.size()) - 1);
  std::uniform_int_distribution<int> small(0, 400);
  long pixels = 0;
  for (int t = 0; t < 60; ++t) {
    // thin or small triangles keep the pixel count in check: two vertices anywhere, the third near one.
    const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
    const int x2 = std::clamp(x1 + small(rng) - 200, 0, 2047 * 16),
              y2 = std::clamp(y1 + small(rng) - 200, 0, 2047 * 16);
    pixels += check_error_bound({x0, y0, x1, y1, x2, y2}, {lights[light(rng)], lights[light(rng)], lights[light(rng)]});
  }
  EXPECT_GT(pixels, 1000);
}

namespace {
// The channel statements behind (i)–(iii) of two_pass_triangle.hpp, for both wrap-side signs σ of
// every channel, in exact integers (×|det|, or ×den for the plane point w = X + (num/den)·(Y − X),
// tt::point_w: the one construction of w, shared with the brute force):
//   (A) not aligned on both axes:  σ·(L_c − P_c(p)) < W;
//   (B) aligned on both:           σ·(L_c − P_c(p)) < 1 + a + b;
//   (C) aligned on both:           σ·L_c < σ·P_c(w) + W (w = p: then also a + b < max(a_Y, b_X)),
// and w in the closed triangle. Summing them with weights |n_c| gives (i)–(iii) for every normal.
// Written apart from two_pass_triangle/triangle_brute_force.cpp (the pixel set by edge functions or the
// pipeline's rasteriser, the light by tt::pixel_light per pixel, P_c(w) as the convex combination
// of two vertex values, the statements spelled out), so the brute force is checked against it.
enum class pixel_set { covered, closed_triangle };
struct statement_count {
  long pixels = 0, both_aligned = 0, on_segment = 0, at_pixel = 0, w_outside = 0, beyond_window = 0;
  std::array<long, 3> checked{}, violations{};  // A, B, C; violations: pixels breaking it
  std::array<std::int64_t, 3> max_ppm{INT64_MIN, INT64_MIN, INT64_MIN};
  std::array<std::uint64_t, 3> first_violation{UINT64_MAX, UINT64_MAX, UINT64_MAX};  // case·2^22 + py·2^11 + px
};

// Twice the signed area of (u, v, q), all in 1/16 pixel (×scale for q).
std::int64_t edge_fn(std::int64_t ux, std::int64_t uy, std::int64_t vx, std::int64_t vy, std::int64_t qx,
                     std::int64_t qy, std::int64_t scale) {
  return (vx - ux) * (qy - uy * scale) - (vy - uy) * (qx - ux * scale);
}
bool closed_inside(const std::array<int, 6>& v, std::int64_t qx, std::int64_t qy, std::int64_t scale,
                   std::int64_t det) {
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t j = (k + 1) % 3;
    const std::int64_t e = edge_fn(v[2 * k], v[2 * k + 1], v[2 * j], v[2 * j + 1], qx, qy, scale);
    if ((det > 0 && e < 0) || (det < 0 && e > 0)) return false;
  }
  return true;
}

void check_statements(const std::array<int, 6>& xy16, const std::array<p::ivec3, 3>& lights, int W, statement_count& n,
                      pixel_set which = pixel_set::covered, std::uint64_t index = 0) {
  const tt::triangle_case c{100, 0, 0, lights, xy16, 0, 0};
  const auto setup =
      pl::setup_triangle({pl::xy124{xy16[0], xy16[1]}, pl::xy124{xy16[2], xy16[3]}, pl::xy124{xy16[4], xy16[5]}});
  if (setup.area2 == 0) return;
  const auto edge = tt::lag_edge_of(xy16);
  const int rx = edge.rx, ry = edge.ry;
  ASSERT_EQ(rx, (std::min({xy16[0], xy16[2], xy16[4]}) + 15) >> 4);
  ASSERT_EQ(ry, (std::min({xy16[1], xy16[3], xy16[5]}) + 15) >> 4);
  const std::int64_t ax = xy16[2] - xy16[0], ay = xy16[3] - xy16[1], bx = xy16[4] - xy16[0], by = xy16[5] - xy16[1];
  const std::int64_t det = ax * by - bx * ay, ad = det < 0 ? -det : det, sd = det < 0 ? -1 : 1;
  const std::size_t X = edge.X, Y = edge.Y;
  auto vertex_value = [&](std::size_t k, std::size_t ch) { return std::int64_t{128} * (128 + lights[k][ch]); };
  auto at_pixel = [&](int x, int y) {
    tt::triangle_case k = c;
    k.px = x, k.py = y;
    const auto cf = tt::pixel_light(k);
    const std::int64_t L[3] = {cf.r.value(), cf.g.value(), cf.b.value()};
    const std::int64_t a = x - rx, b = y - ry, qx = 16 * x - xy16[0], qy = 16 * y - xy16[1];
    ASSERT_TRUE(a >= 0 && b >= 0);
    n.beyond_window += a > W - 1 || b > W - 1;  // the premise a, b <= W − 1 (a shrunk W breaks it on purpose)
    const tt::plane_point w = tt::point_w(edge, x, y);
    if (!w.at_pixel()) {
      const std::int64_t wx = xy16[2 * X] * (w.den - w.num) + xy16[2 * Y] * w.num,
                         wy = xy16[2 * X + 1] * (w.den - w.num) + xy16[2 * Y + 1] * w.num;
      n.w_outside += !closed_inside(xy16, wx, wy, w.den, det);
    }
    const std::uint64_t at = index << 22 | static_cast<std::uint64_t>(y) << 11 | static_cast<std::uint64_t>(x);
    bool broken[3] = {};
    auto check = [&](std::size_t s, std::int64_t left, std::int64_t allowance) {
      ++n.checked[s];
      broken[s] = broken[s] || left >= allowance;
      n.max_ppm[s] = std::max(
          n.max_ppm[s], static_cast<std::int64_t>(std::floor(static_cast<long double>(left) * 1000000 / allowance)));
    };
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const std::int64_t d1 = lights[1][ch] - lights[0][ch], d2 = lights[2][ch] - lights[0][ch];
      const std::int64_t gx = (d1 * by - d2 * ay) * sd, gy = (d2 * ax - d1 * bx) * sd;  // signs of the exact gradient
      const std::int64_t Pdet =
          128 * ((128 + lights[0][ch]) * det + d1 * (by * qx - bx * qy) + d2 * (ax * qy - ay * qx)) * sd;
      for (int sigma : {1, -1}) {
        if (!(sigma * gx < 0 && sigma * gy < 0)) {
          check(0, sigma * (L[ch] * ad - Pdet), W * ad);
          continue;
        }
        ++n.both_aligned;
        check(1, sigma * (L[ch] * ad - Pdet), (1 + a + b) * ad);
        if (!w.at_pixel()) {
          ++n.on_segment;
          const std::int64_t Pw = (w.den - w.num) * vertex_value(X, ch) + w.num * vertex_value(Y, ch);  // P_c(w)·den
          check(2, sigma * L[ch] * w.den - sigma * Pw, W * w.den);
        } else {
          ++n.at_pixel;
          EXPECT_LT(16 * (a + b), std::max({edge.aY, edge.bX, std::int64_t{0}})) << x << " " << y;
          check(2, sigma * (L[ch] * ad - Pdet), W * ad);
        }
      }
    }
    for (std::size_t s = 0; s < 3; ++s)
      if (broken[s]) {
        if (n.violations[s]++ == 0) n.first_violation[s] = at;
      }
    ++n.pixels;
  };
  if (which == pixel_set::covered) {
    pl::rasterise_triangle(setup, pl::scissor{0, 0, 2048, 2048}, at_pixel);
    return;
  }
  const int x1 = std::max({xy16[0], xy16[2], xy16[4]}) / 16, y1 = std::max({xy16[1], xy16[3], xy16[5]}) / 16;
  for (int y = 0; y <= y1; ++y)
    for (int x = 0; x <= x1; ++x)
      if (closed_inside(xy16, 16 * x, 16 * y, 1, det)) at_pixel(x, y);
}

void expect_hold(const statement_count& n) {
  for (std::size_t s = 0; s < 3; ++s)
    EXPECT_EQ(n.violations[s], 0) << "statement "
                                  << "ABC"[s];
  EXPECT_EQ(n.w_outside, 0);
  EXPECT_EQ(n.beyond_window, 0);
}

// The lattice cases of the small window: every ordered triple of distinct points of small_lattice(),
// each with the lights of L_12 by a fixed rotation and by a second one that keeps them near each
// other (small gradients, whose fractions are all of the step: where two-axis lag is largest).
template <class F>
void for_each_window_case(F&& f) {
  const auto lights = p::packed_lights(12);
  const auto pts = small_lattice();
  long k = 0;
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = 0; b < pts.size(); ++b)
      for (std::size_t c = 0; c < pts.size(); ++c) {
        if (a == b || b == c || a == c) continue;
        ++k;
        const std::size_t base = static_cast<std::size_t>(k * 7919) % lights.size();
        const std::array<int, 6> xy{pts[a][0], pts[a][1], pts[b][0], pts[b][1], pts[c][0], pts[c][1]};
        f(xy, std::array<p::ivec3, 3>{lights[(k * 7919) % lights.size()], lights[(k * 104729) % lights.size()],
                                      lights[(k * 1299709) % lights.size()]});
        f(xy, std::array<p::ivec3, 3>{lights[base], lights[(base + 1 + k % 3) % lights.size()],
                                      lights[(base + 2 + k % 5) % lights.size()]});
      }
}
}  // namespace

TEST(Triangle, ChannelStatementsHoldOnEveryLatticeTriangleOfASmallWindow) {
  // The 5 × 5 lattice of the test above (coordinates <= 95/16 pixel: W = 7), every pixel the rasteriser covers.
  statement_count n;
  for_each_window_case(
      [&](const std::array<int, 6>& xy, const std::array<p::ivec3, 3>& l) { check_statements(xy, l, 7, n); });
  expect_hold(n);
  EXPECT_GT(n.pixels, 20000);
  EXPECT_GT(n.on_segment, 1000);  // both branches of (i) are exercised
  EXPECT_GT(n.at_pixel, 100);
}

TEST(Triangle, BruteForceAgreesWithTheWindowEnumerationOnEveryLatticeTriangleOfASmallWindow) {
  // tt::check_case (the --brute-force loop) against check_statements over the closed triangles of the
  // same cases: the same pixels, instances, violations, first witnesses and largest ratios. W = 7 is
  // the window (every statement holds); W = 3 is not (a, b reach 5), so (A) and (C) must fail the same way.
  for (int W : {7, 3}) {
    statement_count n;
    tt::brute_force_acc acc;
    std::uint64_t index = 0;
    for_each_window_case([&](const std::array<int, 6>& xy, const std::array<p::ivec3, 3>& l) {
      check_statements(xy, l, W, n, pixel_set::closed_triangle, index);
      tt::check_case(tt::triangle_case{0, 0, 0, l, xy, 0, 0}, index, W, acc);
      ++index;
    });
    EXPECT_EQ(static_cast<long>(acc.pixels), n.pixels) << "W " << W;
    EXPECT_EQ(static_cast<long>(acc.w_outside.count), n.w_outside);
    for (std::size_t s = 0; s < 3; ++s) {
      const auto& st = acc.statement[s];
      EXPECT_EQ(tt::channel_statements()[s].name, std::string(1, "ABC"[s]));
      EXPECT_EQ(static_cast<long>(st.checked), n.checked[s]) << "W " << W << " statement " << s;
      EXPECT_EQ(static_cast<long>(st.violations.count), n.violations[s]) << "W " << W << " statement " << s;
      EXPECT_NEAR(static_cast<double>(st.ratio_ppm.max), static_cast<double>(n.max_ppm[s]), 1.0)
          << "W " << W << " statement " << s;
      if (n.violations[s] > 0) {
        EXPECT_EQ(st.violations.first[0], n.first_violation[s]) << "W " << W << " statement " << s;
      }
    }
    if (W == 7) {
      expect_hold(n);
      EXPECT_GT(n.pixels, 20000);
    } else {
      EXPECT_GT(n.violations[0], 0);  // the comparison covers a failing run
      EXPECT_GT(n.violations[2], 0);
      EXPECT_EQ(n.violations[1], 0);  // (B)'s allowance does not involve W
      // a witness names its failure
      const std::uint64_t at = acc.statement[0].violations.first[0];
      std::uint64_t k = 0;
      for_each_window_case([&](const std::array<int, 6>& xy, const std::array<p::ivec3, 3>& l) {
        if (k++ != at >> 22) return;
        const std::string what = tt::failures_at(
            tt::triangle_case{0, 0, 0, l, xy, static_cast<int>(at & 2047), static_cast<int>(at >> 11 & 2047)}, W);
        EXPECT_NE(what.find("(A)"), std::string::npos) << what;
      });
    }
  }
}

TEST(Triangle, ChannelStatementsHoldOnRandomFullSizeTriangles) {
  // Right and general triangles across the whole window (W = 2048), lights of L_98 close to each
  // other so that the steps' fractions are large, as in the certificates.
  std::mt19937_64 rng(98);
  const auto lights = p::packed_lights(98);
  std::uniform_int_distribution<int> coord(0, 2047 * 16), light(0, static_cast<int>(lights.size()) - 1), near(0, 40);
  statement_count n;
  for (int t = 0; t < 40; ++t) {
    // a thin sliver (few pixels) from one corner region to another keeps the pixel count small
    const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
    const int x2 = std::clamp(x1 + near(rng) * 8 - 160, 0, 2047 * 16),
              y2 = std::clamp(y1 + near(rng) * 8 - 160, 0, 2047 * 16);
    const auto l0 = lights[static_cast<std::size_t>(light(rng))];
    const std::size_t j = static_cast<std::size_t>(light(rng));
    check_statements({x0, y0, x1, y1, x2, y2},
                     {l0, lights[j], lights[(j + 1 + static_cast<std::size_t>(near(rng))) % lights.size()]}, 2048, n);
  }
  expect_hold(n);
  EXPECT_GT(n.pixels, 1000);
}

namespace {
// (iii)'s bound in doubles, written from its closed form: for every set D leaving out a nonzero
// channel and θ_c = k/16, R·(|α| + |β|) + K; the least over the grid, the greatest over D, and case
// (i) R·|n| + |n|_1·W (the light's; the truncation of truncate_to_8 comes on top, per side).
double reach_double(const double n[3], int s) {
  const double R = 128.0 * s, W = 2048, l1 = n[0] + n[1] + n[2];
  double reach = R * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + l1 * W;
  for (unsigned d = 1; d < 8; ++d) {
    bool proper = false, inside = true;
    for (unsigned c = 0; c < 3; ++c) {
      if ((d >> c & 1) && n[c] == 0) inside = false;
      if (!(d >> c & 1) && n[c] != 0) proper = true;
    }
    if (!inside || !proper) continue;
    double least = 1e300;
    const int range[3] = {(d & 1) ? 17 : 1, (d & 2) ? 17 : 1, (d & 4) ? 17 : 1};
    for (int t = 0; t < range[0] * range[1] * range[2]; ++t) {
      const int k[3] = {t % range[0], t / range[0] % range[1], t / (range[0] * range[1])};
      double a2 = 0, b2 = 0, K = 0;
      for (unsigned c = 0; c < 3; ++c) {
        if (!(d >> c & 1)) {
          a2 += n[c] * n[c], K += n[c] * W;
          continue;
        }
        const double th = k[c] / 16.0;
        a2 += th * th * n[c] * n[c], b2 += (1 - th) * (1 - th) * n[c] * n[c],
            K += n[c] * (th * (2 * W - 1) + (1 - th) * W);
      }
      least = std::min(least, R * (std::sqrt(a2) + std::sqrt(b2)) + K);
    }
    reach = std::max(reach, least);
  }
  return reach;
}
}  // namespace

TEST(Triangle, TwoPointBoundIsAtLeastTheMaximumOverTheIntegerPointsOfASmallBall) {
  // (iii) for one D against brute force: every pair v, u of integer points with |v|, |u| <= R = 5,
  // W = 3, the bracket Σ_{c∉D} n_c·(v_c + W) + Σ_{c∈D} n_c·min(v_c + 2W − 1, u_c + W) at its
  // maximum; the bound must not be below it, and for some D it is below (ii)'s θ = 1 value.
  constexpr int R = 5, W = 3;
  std::vector<std::array<int, 3>> ball;
  for (int x = -R; x <= R; ++x)
    for (int y = -R; y <= R; ++y)
      for (int z = -R; z <= R; ++z)
        if (x * x + y * y + z * z <= R * R) ball.push_back({x, y, z});
  int tighter = 0, checked = 0;
  for (const std::array<std::int64_t, 3>& n : {std::array<std::int64_t, 3>{3, 1, 2}, {0, 2, 5}, {4, 4, 1}, {1, 1, 1}}) {
    for (unsigned d = 1; d < 8; ++d) {
      unsigned nonzero = 0;
      for (unsigned c = 0; c < 3; ++c) nonzero |= (n[c] != 0 ? 1u : 0u) << c;
      if ((d & nonzero) != d || d == nonzero) continue;
      std::int64_t best = std::numeric_limits<std::int64_t>::min(), theta_one = 0;
      for (const auto& v : ball)
        for (const auto& u : ball) {
          std::int64_t sum = 0;
          for (unsigned c = 0; c < 3; ++c)
            sum += (d >> c & 1) ? n[c] * std::min(v[c] + 2 * W - 1, u[c] + W) : n[c] * (v[c] + W);
          best = std::max(best, sum);
        }
      const std::int64_t bound = tt::two_point_units(n, d, R, W);
      EXPECT_GE(bound, best) << n[0] << " " << n[1] << " " << n[2] << " D " << d;
      // θ = 1: R·|n| + Σ_D n_c·(2W − 1) + Σ_rest n_c·W, with |n| rounded up to an integer as (ii) takes it
      const std::int64_t n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      std::int64_t len = 0;
      while (len * len < n2) ++len;
      theta_one = R * len;
      for (unsigned c = 0; c < 3; ++c) theta_one += n[c] * ((d >> c & 1) ? 2 * W - 1 : W);
      EXPECT_LE(bound, theta_one);
      tighter += bound < theta_one;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 20);
  EXPECT_GT(tighter, 0);
}

TEST(Triangle, BoundedSafeSIsWhatTheInequalityGivesForTheWorstNormal) {
  // Independent form (reach_double, every normal, no pruning): every normal is safe at bound_safe_s
  // by the inequality (and so below it: the reach grows with s), and some normal is not at s + 1.
  for (auto g : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
    gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
    o.gouraud = g;
    const p::two_pass::table t(o);
    const int s_max = tt::bound_safe_s(o);
    bool fails_above = false;
    for (const auto& nm : p::appendix2_normals()) {
      const double n[3] = {double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))};
      const int neg = (nm.iX < 0) + (nm.iY < 0) + (nm.iZ < 0), pos = (nm.iX > 0) + (nm.iY > 0) + (nm.iZ > 0),
                e = t.alpha_error(nm);
      const double gb = floor_give_back(g);
      // truncate_to_8: the multiply's light is at most 127/128 level above the Gouraud light on the
      // channels whose σ is −1 (n_c < 0 at the top, n_c > 0 at the bottom; TruncateToEightGivesBack
      // AtMost127Units checks the 127)
      double top_cut = 0, bottom_cut = 0;
      if (g == gs::gouraud_fraction::truncate_to_8)
        for (int c : {nm.iX, nm.iY, nm.iZ}) (c < 0 ? top_cut : bottom_cut) += 127.0 * std::abs(c);
      auto safe = [&](int s) {
        const double reach = reach_double(n, s);
        return (reach + top_cut) / 16384 + neg * gb + e < 128 && -(reach + bottom_cut) / 16384 - pos * gb + e > -129;
      };
      EXPECT_TRUE(safe(s_max)) << nm.iX << " " << nm.iY;
      fails_above = fails_above || !safe(s_max + 1);
    }
    EXPECT_TRUE(fails_above);
  }
}

TEST(Triangle, PerPixelSafeSIsWhatTheBallOrTheLightSupportGives) {
  // gouraud_setup = per_pixel: |L_c − P_c(p)| < 1 unit, P(p) a convex combination of the vertex lights,
  // so n·(L − centre) < min(R·|n|, 128·max over L_s of Σ|n_c|·|l_c|) + |n|_1 (in doubles and by a scan of
  // the packed lights here). Every normal is safe at bound_safe_s = 125 that way, and at 126 the
  // vertex claim's witness normal is not (the flat certificate wraps there).
  gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
  o.setup = gs::gouraud_setup::per_pixel;
  const p::two_pass::table t(o);
  ASSERT_EQ(tt::bound_safe_s(o), 125);
  const auto lights = p::packed_lights(125);
  int by_support = 0;
  for (const auto& nm : p::appendix2_normals()) {
    const double n[3] = {double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))};
    const double l1 = n[0] + n[1] + n[2];
    const int neg = (nm.iX < 0) + (nm.iY < 0) + (nm.iZ < 0), pos = (nm.iX > 0) + (nm.iY > 0) + (nm.iZ > 0);
    const int e = t.alpha_error(nm);
    const double gb = floor_give_back(o.gouraud);
    auto safe = [&](double reach) {
      return reach / 16384 + neg * gb + e < 128 && -reach / 16384 - pos * gb + e > -129;
    };
    if (safe(128.0 * 125 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + l1)) continue;
    double support = 0;
    for (const auto& l : lights)
      support = std::max(support, n[0] * std::abs(l[0]) + n[1] * std::abs(l[1]) + n[2] * std::abs(l[2]));
    EXPECT_TRUE(safe(128 * support + l1)) << nm.iX << " " << nm.iY;
    ++by_support;
  }
  EXPECT_GT(by_support, 0);  // the ball alone does not reach 125
  const auto w = p::paper::pack_normal_from(-127, -15);
  EXPECT_FALSE(tt::cannot_wrap(w, t.alpha_error(w), 126, o, p::packed_lights(126)));
}

TEST(Triangle, BallSupportLightsGiveTheWholeBallsSupport) {
  // The reduction of ball_support_lights against a scan of every cell of the ball (attenuated_lights)
  // at s = 16 and 17, for every normal of the normal map.
  for (int s : {16, 17}) {
    const auto ball = p::attenuated_lights(s), surface = tt::ball_support_lights(s);
    ASSERT_LT(surface.size(), ball.size() / 20);
    for (const auto& nm : p::appendix2_normals()) {
      const std::array<std::int64_t, 3> n{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
      std::int64_t whole = 0;
      for (const auto& l : ball)
        whole = std::max(whole, n[0] * std::abs(l[0]) + n[1] * std::abs(l[1]) + n[2] * std::abs(l[2]));
      ASSERT_EQ(tt::light_support(n, surface), whole) << s << " " << nm.iX << " " << nm.iY;
    }
  }
}

TEST(Triangle, PerPixelTruncatedSafeSIsWhatTheInequalityGives) {
  // The dobiestation profile (per_pixel with truncate_to_8): the same inequality in doubles with the
  // multiply's floor adding up to 127/128 level on each channel against the side (n_c < 0 at the top,
  // > 0 at the bottom). Every normal is safe at bound_safe_s = 123 that way, and some normal is not
  // at 124 (where the certificate of certificates.csv wraps).
  gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
  o.setup = gs::gouraud_setup::per_pixel;
  o.gouraud = gs::gouraud_fraction::truncate_to_8;
  const p::two_pass::table t(o);
  const int s_max = tt::bound_safe_s(o);
  EXPECT_EQ(s_max, 123);
  const auto at = p::packed_lights(s_max), above = p::packed_lights(s_max + 1);
  bool fails_above = false;
  for (const auto& nm : p::appendix2_normals()) {
    const double n[3] = {double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))};
    const double l1 = n[0] + n[1] + n[2], len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const int neg = (nm.iX < 0) + (nm.iY < 0) + (nm.iZ < 0), pos = (nm.iX > 0) + (nm.iY > 0) + (nm.iZ > 0);
    const int e = t.alpha_error(nm);
    double top_cut = 0, bottom_cut = 0;
    for (int c : {nm.iX, nm.iY, nm.iZ}) (c < 0 ? top_cut : bottom_cut) += 127.0 * std::abs(c);
    auto safe = [&](double reach) {
      const double gb = floor_give_back(o.gouraud);
      return (reach + top_cut) / 16384 + neg * gb + e < 128 && -(reach + bottom_cut) / 16384 - pos * gb + e > -129;
    };
    auto safe_at = [&](int s, const std::vector<p::ivec3>& lights) {
      if (safe(128.0 * s * len + l1)) return true;
      double support = 0;
      for (const auto& l : lights)
        support = std::max(support, n[0] * std::abs(l[0]) + n[1] * std::abs(l[1]) + n[2] * std::abs(l[2]));
      return safe(128 * support + l1);
    };
    EXPECT_TRUE(safe_at(s_max, at)) << nm.iX << " " << nm.iY;
    fails_above = fails_above || !safe_at(s_max + 1, above);
  }
  EXPECT_TRUE(fails_above);
}

TEST(Triangle, FloorsGiveBackAtMostG) {
  // The bound's value statement (two_pass_triangle.hpp, floor_slack_units): with M_c the light the
  // multiply sees, 16384·(value − e) − Σ n_c·(M_c − 16384) lies in [−G·#{n_c > 0}, G·#{n_c < 0}], G =
  // 16384 − floor_slack_units = 16383 (keep_fraction) or 16256 (truncate_to_8). Every Appendix 2
  // normal against random 15-bit lights and the two extreme ones, through the model's two-pass
  // value, under every tfx_rounding × blend_shift (the claim's other options); each end comes within a
  // level of being reached (the statement is not loose).
  std::mt19937 rng(1313);
  std::uniform_int_distribution<int> unit(0, 0x7FFF);
  for (int combo = 0; combo < 8; ++combo) {
    const auto g = combo & 1 ? gs::gouraud_fraction::truncate_to_8 : gs::gouraud_fraction::keep_fraction;
    gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
    o.gouraud = g;
    o.tfx = combo & 2 ? gs::tfx_rounding::truncate : gs::tfx_rounding::floor;
    o.shift = combo & 4 ? gs::blend_shift::truncate : gs::blend_shift::floor;
    const p::two_pass::table t(o);
    const std::int64_t G = 16384 - tt::floor_slack_units(o);
    EXPECT_EQ(G, g == gs::gouraud_fraction::keep_fraction ? 16383 : 16256);
    std::int64_t closest_top = std::numeric_limits<std::int64_t>::max(), closest_bottom = closest_top;
    std::int64_t cases = 0;
    for (const auto& nm : p::appendix2_normals()) {
      const int n[3] = {nm.iX, nm.iY, nm.iZ};
      const int neg = (n[0] < 0) + (n[1] < 0) + (n[2] < 0), pos = (n[0] > 0) + (n[1] > 0) + (n[2] > 0);
      const int e = t.alpha_error(nm);
      for (int k = 0; k < 6; ++k) {
        int L[3];
        for (int& v : L) v = k == 0 ? 0 : k == 1 ? 0x7FFF : unit(rng);
        const gs::fragment_colour cf{gs::gouraud_channel::from_wrapped(L[0]), gs::gouraud_channel::from_wrapped(L[1]),
                                     gs::gouraud_channel::from_wrapped(L[2]),
                                     gs::gouraud_channel::from_wrapped(0x4000)};
        const int value = p::two_pass::pixel(nm, cf, o).value;
        std::int64_t d = std::int64_t{16384} * (value - e);
        for (int c = 0; c < 3; ++c) {
          const int M = g == gs::gouraud_fraction::truncate_to_8 ? (L[c] >> 7) << 7 : L[c];
          d -= std::int64_t{n[c]} * (M - 16384);
        }
        ASSERT_LE(d, G * neg) << nm.iX << " " << nm.iY << " " << L[0] << " " << L[1] << " " << L[2];
        ASSERT_GE(d, -G * pos) << nm.iX << " " << nm.iY << " " << L[0] << " " << L[1] << " " << L[2];
        closest_top = std::min(closest_top, G * neg - d);
        closest_bottom = std::min(closest_bottom, d + G * pos);
        ++cases;
      }
    }
    EXPECT_EQ(cases, std::int64_t{6} * static_cast<std::int64_t>(p::appendix2_normals().size()));
    EXPECT_LT(closest_top, 16384);
    EXPECT_LT(closest_bottom, 16384);
  }
}

TEST(Triangle, TruncateToEightGivesBackAtMost127Units) {
  // The bound's truncation_units: under truncate_to_8 the multiply sees the Gouraud light with its
  // fraction cut, 128·floor(L/128), and L is a whole number of 8.7 units, so the cut is 0 .. 127 units,
  // never 128. Every 15-bit Gouraud value through gs::integer_part (modulate_channel's input under
  // truncate_to_8); and the largest cut, 127, is what truncation_units charges per unit of |n_c|
  // against the side.
  int most = -1;
  for (int L = 0; L <= 0x7FFF; ++L) {
    const int seen = 128 * static_cast<int>(gs::integer_part(gs::gouraud_channel::from_wrapped(L)).value());
    ASSERT_LE(seen, L);
    most = std::max(most, L - seen);
  }
  EXPECT_EQ(most, 127);
  gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
  o.gouraud = gs::gouraud_fraction::truncate_to_8;
  const auto nm = p::paper::pack_normal_from(60, 67);  // all three components > 0: every channel is against the bottom
  EXPECT_EQ(tt::truncation_units(nm, -1, o), 127 * (nm.iX + nm.iY + nm.iZ));
  EXPECT_EQ(tt::truncation_units(nm, 1, o), 0);
}

TEST(Triangle, AZeroNormalComponentAddsNothingWhateverItsLight) {
  // The bottom threshold counts #{n_c > 0}, not #{n_c >= 0}: a zero component's two products are 0
  // whatever its light. Every Appendix 2 normal with a zero x or y, that channel's light over every
  // 8.7 value, both gouraud_fraction values: the value does not move.
  int normals = 0;
  for (auto g : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
    gs::model_options o{.setup = gs::gouraud_setup::plane_steps};
    o.gouraud = g;
    for (const auto& nm : p::appendix2_normals()) {
      if (nm.iX != 0 && nm.iY != 0) continue;
      ++normals;
      gs::fragment_colour f = gs::fragment_colour::flat(gs::rgba8::from_u32(0x80406080u));
      const int first = p::two_pass::pixel(nm, f, o).value;
      for (int v = 0; v <= 0x7FFF; v += 7) {
        if (nm.iX == 0) f.r = gs::gouraud_channel::from_wrapped(v);
        if (nm.iY == 0) f.g = gs::gouraud_channel::from_wrapped(v);
        ASSERT_EQ(p::two_pass::pixel(nm, f, o).value, first) << nm.iX << " " << nm.iY << " " << v;
      }
    }
  }
  EXPECT_GT(normals, 2);
}

namespace {
// The plane through the three vertex lights of one channel, written another way: Cramer's rule on
// [x y 1]·(g_x, g_y, c) = l at the three vertices (levels; g per pixel).
std::array<double, 3> plane_by_cramer(const tt::relaxation_point& x, std::size_t c,
                                      const std::array<std::array<double, 3>, 3>& l) {
  const auto& V = x.vertex;
  auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double A[3][3] = {{V[0][0], V[0][1], 1}, {V[1][0], V[1][1], 1}, {V[2][0], V[2][1], 1}};
  const double d = det3(A);
  std::array<double, 3> out{};
  for (int col = 0; col < 3; ++col) {
    double M[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) M[r][k] = k == col ? l[static_cast<std::size_t>(r)][c] : A[r][k];
    out[static_cast<std::size_t>(col)] = det3(M) / d;
  }
  return out;  // g_x, g_y, constant
}
}  // namespace

TEST(Triangle, RelaxationWitnessesLieInTheRelaxationAndExceedTheirThresholds) {
  for (const auto& w : tt::relaxation_witnesses()) {
    gs::model_options o{.setup = gs::gouraud_setup::plane_steps};  // the relaxation bounds plane_steps' lag
    o.gouraud = w.gouraud;
    const p::two_pass::table t(o);
    const auto nm = p::paper::pack_normal_from(w.iX, w.iY);
    const std::array<double, 3> n{double(std::abs(nm.iX)), double(std::abs(nm.iY)), double(std::abs(nm.iZ))};
    // the domain: vertices in the window with r = (0, 0) their least coordinates, p a point of the triangle
    double least_x = 1e9, least_y = 1e9;
    for (const auto& v : w.at.vertex) {
      EXPECT_TRUE(v[0] >= 0 && v[0] <= 2047 && v[1] >= 0 && v[1] <= 2047) << w.s;
      least_x = std::min(least_x, v[0]), least_y = std::min(least_y, v[1]);
    }
    EXPECT_EQ(least_x, 0);
    EXPECT_EQ(least_y, 0);
    // the lights, scaled onto the ball as relaxation_value does, then the objective by Cramer's rule
    auto l = w.at.light;
    for (auto& v : l) {
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      EXPECT_LT(len, w.s + 0.01) << "a witness light is far outside the ball";
      if (len > w.s)
        for (double& c : v) c *= w.s / len;
    }
    double value = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const auto g = plane_by_cramer(w.at, c, l);
      const double P = g[0] * w.at.pixel[0] + g[1] * w.at.pixel[1] + g[2];
      value += n[c] * (P + w.at.pixel[0] * std::clamp(-128 * g[0], 0.0, 1.0) / 128 +
                       w.at.pixel[1] * std::clamp(-128 * g[1], 0.0, 1.0) / 128);
    }
    EXPECT_NEAR(tt::relaxation_value(w.at, n, w.s), value, 1e-6) << w.s;
    const double l1 = n[0] + n[1] + n[2];
    const int neg = (nm.iX < 0) + (nm.iY < 0) + (nm.iZ < 0);
    // truncate_to_8: up to 127/128 level more on the channels against the side (n_c < 0 at the top,
    // > 0 at the bottom), and there each product's floor gives back at most 127/128 (16383/16384 under
    // keep_fraction) of the level the threshold's count charges: 1/128 (1/16384) of |n|·level back per
    // channel counted
    const bool truncate = w.gouraud == gs::gouraud_fraction::truncate_to_8;
    double against = 0;
    int counted = 0;
    for (int c : {nm.iX, nm.iY, nm.iZ}) against += w.side * c < 0 ? std::abs(c) : 0, counted += w.side * c < 0;
    const int e = t.alpha_error(nm);
    const double threshold = (w.side > 0 ? 128.0 * (128 - neg - e) : 128.0 * (129 - (3 - neg) + e)) +
                             counted * 128 * (1 - floor_give_back(w.gouraud));
    const double margin = value + l1 / 128 + (truncate ? against * 127 / 128 : 0) - threshold;
    EXPECT_NEAR(tt::relaxation_margin(w, t, o), margin, 1e-6);
    // well above the doubles' rounding (~1e-9 here): the s = 83 truncate_to_8 row by 0.018, the s = 84 one by 77
    EXPECT_GT(margin, 0.01) << "s = " << w.s << ": the witness should clear its threshold by more than its rounding";
    // and the bound itself cannot settle that normal at that s (else the witness would say nothing)
    EXPECT_FALSE(tt::cannot_wrap(nm, t.alpha_error(nm), w.s, o)) << w.s;
  }
}

TEST(Triangle, RelaxationIsAnUpperBoundOnEveryCertificatesPixel) {
  // The relaxation's lag statement on real cases: for every certificate (its own wrap side) the
  // pixel's light, through the model's Gouraud set-up, stays below the relaxation's value at the
  // same vertices, pixel and (integer) lights plus the start error's |n|_1/128.
  int checked = 0;
  for (const auto& c : tt::certificates()) {
    const auto nm = p::paper::pack_normal_from(c.iX, c.iY);
    const int n[3] = {nm.iX, nm.iY, nm.iZ};
    const auto r = tt::reference_pixel(c.xy16);
    const auto L = tt::pixel_light(c);
    const int Lc[3] = {L.r.value(), L.g.value(), L.b.value()};
    for (int side : {1, -1}) {
      tt::relaxation_point x{};
      for (std::size_t k = 0; k < 3; ++k) x.vertex[k] = {c.xy16[2 * k] / 16.0 - r[0], c.xy16[2 * k + 1] / 16.0 - r[1]};
      x.pixel = {double(c.px - r[0]), double(c.py - r[1])};
      std::array<double, 3> w{};
      double actual = 0, l1 = 0;
      for (std::size_t ch = 0; ch < 3; ++ch) {
        const int sigma = side * (n[ch] >= 0 ? 1 : -1);
        w[ch] = std::abs(n[ch]), l1 += w[ch];
        for (std::size_t k = 0; k < 3; ++k) x.light[k][ch] = sigma * c.light[k][ch];
        actual += w[ch] * sigma * (Lc[ch] - 16384) / 128.0;
      }
      EXPECT_LT(actual, tt::relaxation_value(x, w, c.s) + l1 / 128 + 1e-9) << "s = " << c.s << " side " << side;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * static_cast<int>(tt::certificates().size()));
}

namespace {
// Covered pixels of the triangle on the window's last row (y = w − 1) and last column (x = w − 1),
// for a window of w pixels whose vertices lie in 0 .. (w − 1)·16.
// `row` = w − 2 counts the row above instead (which triangles do cover).
int last_row_or_column_covered(const std::array<int, 6>& xy16, int w, int row = -1) {
  const auto setup =
      pl::setup_triangle({pl::xy124{xy16[0], xy16[1]}, pl::xy124{xy16[2], xy16[3]}, pl::xy124{xy16[4], xy16[5]}});
  if (setup.area2 == 0) return 0;
  if (row < 0) row = w - 1;
  int covered = 0;
  for (int k = 0; k < w; ++k) covered += pl::covers(setup, k, row) + pl::covers(setup, row, k);
  return covered;
}
}  // namespace

TEST(Triangle, NoTriangleOfTheWindowCoversItsLastRowOrColumn) {
  // bench/proofs_triangle_free_x (commit 9f63566) put its pixel on row 2046: with every vertex
  // y <= w − 1, a pixel centre on row w − 1 lies on the triangle's boundary, on a bottom edge or at the lowest vertex,
  // which is also on a right edge, and the fill rule covers neither (the same for column w − 1 with
  // right edges). Every triangle of three distinct points of a 9 × 9 lattice (1/4 pixel apart, so the
  // pixel centres themselves are vertices) in a 3-pixel window, and random full-size triangles with
  // a vertex at or near the window's last row or column.
  std::vector<std::array<int, 2>> pts;
  for (int y = 0; y <= 32; y += 4)
    for (int x = 0; x <= 32; x += 4) pts.push_back({x, y});
  long triangles = 0, covered = 0, above = 0;
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); ++b)
      for (std::size_t c = b + 1; c < pts.size(); ++c) {
        ++triangles;
        const std::array<int, 6> xy16{pts[a][0], pts[a][1], pts[b][0], pts[b][1], pts[c][0], pts[c][1]};
        covered += last_row_or_column_covered(xy16, 3);
        above += last_row_or_column_covered(xy16, 3, 1);
      }
  EXPECT_EQ(triangles, 81 * 80 * 79 / 6);
  EXPECT_EQ(covered, 0);
  EXPECT_GT(above, 10000);
  std::mt19937_64 rng(84);
  constexpr int max124 = (tt::window_pixels - 1) * 16;
  std::uniform_int_distribution<int> coord(0, max124), near(max124 - 48, max124);
  long rows = 0;
  for (int t = 0; t < 2000; ++t) {
    const std::array<int, 6> xy16{coord(rng), coord(rng), coord(rng), near(rng), near(rng), t % 2 ? max124 : near(rng)};
    EXPECT_EQ(last_row_or_column_covered(xy16, tt::window_pixels), 0) << "case " << t;
    rows += last_row_or_column_covered(xy16, tt::window_pixels, tt::window_pixels - 2) > 0;  // the row above is covered
  }
  EXPECT_GT(rows, 500);
}
