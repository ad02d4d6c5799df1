// gs_arith_uv_plane — options uv_plane and uv_convert (gs_arith/uv_plane.hpp, docs/evidence.md R12,
// R13) against exact rational arithmetic written here: the exact U at a pixel centre from the three
// vertices is the rational N / D (the barycentric sum of edge functions in 12.4² units over the doubled
// area), and the texel coordinate is floor(N / D) under `floor` and floor(N / D + 1/64) =
// floor((64·N + D) / (64·D)) under `floor_1_64`. uv_plane=exact equals it at every pixel;
// uv_plane=fixed_16 floors its gradients (MODEL-PLANE-16), so it equals the exact value wherever the
// exact value is farther from a boundary than the plane's error bound; the sweeps check exactly those
// pixels and count the ones where the options differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <utility>

#include "gs_arith/options.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/uv_plane.hpp"

namespace {

// Every value below fits in 64 bits: positions under 2^12 in 12.4 units, UVs under 2^14, so each
// edge function is under 2^25, N under 2^41 and 2^16·N + 1024·D under 2^58.
using wide = std::int64_t;

// floor(n / d) for d > 0.
wide floor_q(wide n, wide d) { return n / d - (n % d != 0 && n < 0 ? 1 : 0); }

// The exact U (sixteenths of a texel) at pixel centre (x, y) as N / D with D > 0: the barycentric sum
// Σ E_k·a_k / area, E_k the edge function opposite vertex k, all in 12.4 units.
struct rational {
  wide n, d;
};
rational exact_u(const std::array<gs::xy124, 3>& p, const std::array<std::int32_t, 3>& a, int x, int y) {
  auto cross = [](wide ax, wide ay, wide bx, wide by, wide cx, wide cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const wide px = wide{x} * 16, py = wide{y} * 16;
  const wide area = cross(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y);
  const wide e0 = cross(px, py, p[1].x, p[1].y, p[2].x, p[2].y);
  const wide e1 = cross(p[0].x, p[0].y, px, py, p[2].x, p[2].y);
  const wide e2 = cross(p[0].x, p[0].y, p[1].x, p[1].y, px, py);
  rational r{e0 * a[0] + e1 * a[1] + e2 * a[2], area};
  if (r.d < 0) r.n = -r.n, r.d = -r.d;
  return r;
}
// The exact texel coordinate: floor(U) or floor(U + 1/64).
std::int64_t exact_texel(rational u, gs::uv_convert_mode m) {
  return static_cast<std::int64_t>(m == gs::uv_convert_mode::floor ? floor_q(u.n, u.d)
                                                                   : floor_q(64 * u.n + u.d, 64 * u.d));
}

gs::uv_rule fixed(gs::uv_convert_mode m) { return {gs::uv_plane_mode::fixed_16, m}; }
gs::uv_rule exact(gs::uv_convert_mode m) { return {gs::uv_plane_mode::exact, m}; }

std::string hex_of(std::int64_t v) {
  std::ostringstream s;
  s << v << " (0x" << std::hex << v << ")";
  return s.str();
}

// Hand-picked planes where U lies just below a texel boundary at chosen pixels: expected texels from
// the rationals, and each case's pixel where floor and floor_1_64 part.
struct hand_case {
  const char* what;
  std::array<gs::xy124, 3> p;
  std::array<std::int32_t, 3> u;
  int x, y;
  std::int64_t floor_texel, biased_texel;  // written out by hand, checked against the rationals too
};
const hand_case hand_cases[] = {
    // U = 1054 + 255·x/128: at x = 1, 1055.9921875 (1/128 below 1056; the plane is exact here).
    {"1/128 below, exact plane", {{{0, 0}, {16 * 128, 0}, {0, 16 * 128}}}, {1054, 1054 + 255, 1054}, 1, 0, 1055, 1056},
    // at x = 2, 1057.984375: exactly 1/64 below 1058, which floor(U + 1/64) reaches.
    {"exactly 1/64 below", {{{0, 0}, {16 * 128, 0}, {0, 16 * 128}}}, {1054, 1054 + 255, 1054}, 2, 0, 1057, 1058},
    // at x = 3, 1059.9765625: 3/128 below, more than 1/64: both floor to 1059.
    {"3/128 below", {{{0, 0}, {16 * 128, 0}, {0, 16 * 128}}}, {1054, 1054 + 255, 1054}, 3, 0, 1059, 1059},
    // U = 1000 + 0.99·x (denominator 100, the plane's gradient floored): x = 1 gives 1000.99.
    {"0.01 below, floored gradient", {{{0, 0}, {16 * 100, 0}, {0, 16 * 100}}}, {1000, 1099, 1000}, 1, 0, 1000, 1001},
    {"0.02 below, floored gradient", {{{0, 0}, {16 * 100, 0}, {0, 16 * 100}}}, {1000, 1099, 1000}, 2, 0, 1001, 1001},
    // V along y, as the FINDINGS' (193, 233): V = 4095 + 0.9954 at a pixel, 256-texel texture's last
    // sixteenth (the texel after it wraps to 0 under REPEAT).
    {"V 4095.995", {{{0, 0}, {16 * 217, 0}, {0, 16 * 217}}}, {4095, 4095, 4095 + 216}, 0, 1, 4095, 4096},
};

TEST(UvPlane, HandPickedPixelsJustBelowATexelBoundary) {
  for (const hand_case& c : hand_cases) {
    const rational u = exact_u(c.p, c.u, c.x, c.y);
    ASSERT_EQ(exact_texel(u, gs::uv_convert_mode::floor), c.floor_texel) << c.what;
    ASSERT_EQ(exact_texel(u, gs::uv_convert_mode::floor_1_64), c.biased_texel) << c.what;
    const gs::triangle_setup t = gs::setup_triangle(c.p);
    ASSERT_NE(t.area2, 0);
    ASSERT_TRUE(gs::covers(t, c.x, c.y)) << c.what;
    EXPECT_EQ(gs::make_uv_plane(c.p, c.u, fixed(gs::uv_convert_mode::floor)).at(c.x, c.y), c.floor_texel) << c.what;
    EXPECT_EQ(gs::make_uv_plane(c.p, c.u, fixed(gs::uv_convert_mode::floor_1_64)).at(c.x, c.y), c.biased_texel)
        << c.what;
    EXPECT_EQ(gs::make_uv_plane(c.p, c.u, exact(gs::uv_convert_mode::floor)).at(c.x, c.y), c.floor_texel) << c.what;
    EXPECT_EQ(gs::make_uv_plane(c.p, c.u, exact(gs::uv_convert_mode::floor_1_64)).at(c.x, c.y), c.biased_texel)
        << c.what;
  }
}

// The bias is 1/64 of a sixteenth in plane units, carried in the base: every pixel of a biased plane
// is uv_texel of the unbiased plane's value (what plane::at, gs::attribute_walker and the SIMD rows,
// which all shift (base + dx·x + dy·y) by 16, compute).
TEST(UvPlane, TheBiasedFixedPlaneIsUvTexelOfTheUnbiasedValue) {
  EXPECT_EQ(gs::uv_convert_bias(gs::uv_convert_mode::floor), 0);
  EXPECT_EQ(gs::uv_convert_bias(gs::uv_convert_mode::floor_1_64), 1024);
  const std::array<gs::xy124, 3> p{{{3, 5}, {16 * 90 + 7, 40}, {100, 16 * 70 + 9}}};
  const std::array<std::int32_t, 3> u{16383, 17, 8000};
  const gs::plane plain = gs::make_uv_plane(p, u, fixed(gs::uv_convert_mode::floor));
  const gs::plane biased = gs::make_uv_plane(p, u, fixed(gs::uv_convert_mode::floor_1_64));
  EXPECT_EQ(plain.dx, biased.dx);
  EXPECT_EQ(plain.dy, biased.dy);
  for (int y = -3; y < 80; ++y)
    for (int x = -3; x < 100; ++x) {
      const std::int64_t raw = plain.base + plain.dx * x + plain.dy * y;
      ASSERT_EQ(plain.at(x, y), gs::uv_texel(raw, gs::uv_convert_mode::floor)) << x << ", " << y;
      ASSERT_EQ(biased.at(x, y), gs::uv_texel(raw, gs::uv_convert_mode::floor_1_64)) << x << ", " << y;
    }
}

// Random triangles (fixed seed) with 12.4 positions and 14-bit 12.4 UVs: at every covered pixel whose
// exact value (plus the option's bias) is farther from a texel boundary than the plane's error bound,
// the plane gives the exact texel under both options. The bound: make_plane floors both gradients (an
// error under one plane unit each per pixel from vertex 0) and the base (under one unit), so
// |P − 2^16·U| < |x − x0| + |y − y0| + 1 plane units, x0, y0 vertex 0 in pixels.
TEST(UvPlane, RandomTrianglesFixed16EqualsTheExactRationalsAwayFromTheBound) {
  std::mt19937_64 rng(57);
  std::uniform_int_distribution<std::int32_t> pos(0, 16 * 64), uv(0, 16383);
  long checked = 0, undecided = 0, parted = 0;
  for (int n = 0; n < 3000; ++n) {
    const std::array<gs::xy124, 3> p{{{pos(rng), pos(rng)}, {pos(rng), pos(rng)}, {pos(rng), pos(rng)}}};
    const std::array<std::int32_t, 3> u{uv(rng), uv(rng), uv(rng)};
    const gs::triangle_setup t = gs::setup_triangle(p);
    if (t.area2 == 0) continue;
    const gs::plane plain = gs::make_uv_plane(t.v, {u[0], u[1], u[2]}, fixed(gs::uv_convert_mode::floor));
    const gs::plane biased = gs::make_uv_plane(t.v, {u[0], u[1], u[2]}, fixed(gs::uv_convert_mode::floor_1_64));
    gs::rasterise_triangle(t, {0, 0, 64, 64}, [&](int x, int y) {
      const rational e = exact_u(t.v, u, x, y);
      // plane units, from the vertex make_uv_plane starts at; one more than the bound, to be safe
      const wide bound = (std::abs(16 * x - t.v[0].x) + 15) / 16 + (std::abs(16 * y - t.v[0].y) + 15) / 16 + 2;
      bool both = true;
      for (const auto m : {gs::uv_convert_mode::floor, gs::uv_convert_mode::floor_1_64}) {
        // 2^16·(U + bias) over D, and its distance to the boundaries around it
        const wide w = e.n * 65536 + wide{gs::uv_convert_bias(m)} * e.d, unit = e.d * 65536;
        const wide below = w - floor_q(w, unit) * unit, above = unit - below;
        if (below < bound * e.d || above <= bound * e.d) {
          both = false;
          continue;
        }
        const std::int64_t want = exact_texel(e, m);
        const std::int32_t got = (m == gs::uv_convert_mode::floor ? plain : biased).at(x, y);
        ASSERT_EQ(got, want) << "triangle " << n << " pixel (" << x << ", " << y << ") U = " << hex_of(e.n) << " / "
                             << hex_of(e.d) << ", uv_convert "
                             << (m == gs::uv_convert_mode::floor ? "floor" : "floor_1_64");
        ++checked;
      }
      undecided += !both;
      if (both && exact_texel(e, gs::uv_convert_mode::floor) != exact_texel(e, gs::uv_convert_mode::floor_1_64))
        ++parted;
    });
  }
  // Within 1/64 of a sixteenth below a boundary: about 1/64 of the pixels part the two options.
  EXPECT_GT(checked, 500'000);
  EXPECT_GT(parted, checked / 2 / 200) << "pixels where floor and floor_1_64 differ";
  EXPECT_LT(undecided, checked / 2 / 50) << "pixels within the plane's error bound of a boundary";
}

// uv_plane=exact is the rational at every covered pixel, under both uv_convert values, on random
// triangles (fixed seed) with 12.4 positions and 14-bit UVs, pixel centres on and off the edges; and
// fixed_16 parts from it at some pixels (its floored gradients land below a boundary the exact value
// reaches), which is what the option tells apart.
TEST(UvPlane, ExactPlaneIsTheRationalAtEveryPixel) {
  std::mt19937_64 rng(53);
  std::uniform_int_distribution<std::int32_t> pos(0, 16 * 64), uv(0, 16383), small(0, 48);
  long checked = 0, fixed_parts = 0;
  for (int n = 0; n < 3000; ++n) {
    // every third triangle with whole-pixel vertices and small UVs: exact values on a boundary are common
    const bool grid = n % 3 == 0;
    auto at = [&] { return grid ? 16 * (pos(rng) / 16) : pos(rng); };
    const std::array<gs::xy124, 3> p{{{at(), at()}, {at(), at()}, {at(), at()}}};
    const std::array<std::int32_t, 3> u =
        grid ? std::array{small(rng), small(rng), small(rng)} : std::array{uv(rng), uv(rng), uv(rng)};
    const gs::triangle_setup t = gs::setup_triangle(p);
    if (t.area2 == 0) continue;
    for (const auto m : {gs::uv_convert_mode::floor, gs::uv_convert_mode::floor_1_64}) {
      const gs::plane e = gs::make_uv_plane(t.v, {u[0], u[1], u[2]}, exact(m));
      const gs::plane f = gs::make_uv_plane(t.v, {u[0], u[1], u[2]}, fixed(m));
      gs::rasterise_triangle(t, {0, 0, 64, 64}, [&](int x, int y) {
        const std::int64_t want = exact_texel(exact_u(t.v, u, x, y), m);
        ASSERT_EQ(e.at(x, y), want) << "triangle " << n << " pixel (" << x << ", " << y << ")";
        fixed_parts += f.at(x, y) != want;
        ++checked;
      });
    }
  }
  EXPECT_GT(checked, 1'000'000);
  EXPECT_GT(fixed_parts, 0) << "pixels where fixed_16 and the exact value differ";
  EXPECT_LT(fixed_parts, checked / 20);
}

// The exact plane keeps U within the ±2^20 clamp's range at its largest inputs without overflow: vertex
// UVs of ±2^20 (the perspective path's clamp) on a triangle spanning the 12.4 range.
TEST(UvPlane, ExactPlaneAtTheLargestInputs) {
  const std::array<gs::xy124, 3> p{{{0, 0}, {65535, 7}, {3, 65535}}};
  const std::array<std::int32_t, 3> u{1 << 20, -(1 << 20), 12345};
  const gs::plane e = gs::make_uv_plane(p, u, exact(gs::uv_convert_mode::floor_1_64));
  for (const auto& [x, y] : {std::pair{0, 0}, {4095, 0}, {0, 4095}, {2000, 1000}, {1, 1}})
    EXPECT_EQ(e.at(x, y), std::clamp<std::int64_t>(exact_texel(exact_u(p, u, x, y), gs::uv_convert_mode::floor_1_64),
                                                   -(1 << 20), 1 << 20))
        << x << ", " << y;
}

}  // namespace
