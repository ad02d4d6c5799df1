// The span engine (gs_simd/span_draw.hpp) against the scalar reference, on every SIMD target this CPU
// supports (rapidcheck): a random triangle's attributes (gs::setup_attributes under random model
// options: the UV plane exact and lifted or not, the colour flat, per_pixel_floor or another set-up),
// its rows as runs cut at random (the renderer's runs skip the pixels the depth test drops), a random
// texture (PSMT8 through a CLUT, or 32-bit texels; REPEAT or CLAMP; 2×2 to 64×64) and random
// registers. Every pixel of every run must equal gs::pixel_pipeline(regs, {colour_at, gs::sample of the
// texture at (u.at, v.at), old word, x, y}).out; the frame outside the runs must not change. The sprite
// rows (span_row, span_channel_row) likewise against the scalar chain.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "gs_arith/bilinear.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/span_raster.hpp"
#include "gs_simd/span_draw.hpp"
#include "lanes.hpp"
#include "random_state.hpp"

namespace gsdot3::simd::test {
namespace {

constexpr int width = 72, height = 40;  // the frame: odd-sized rows, wider than four AVX-512 vectors

struct texture {
  int w = 0, h = 0;
  bool clamp = false;
  std::vector<std::uint8_t> index;   // PSMT8, or empty
  std::vector<std::uint32_t> words;  // the CLUT (256) with index, else the texels
  nearest_texture lanes() const {
    nearest_texture t;
    (index.empty() ? t.texels : t.words) = words.data();
    if (!index.empty()) t.index = index.data();
    t.wmask = w - 1, t.hmask = h - 1, t.clamp = clamp;
    for (t.shift = 0; (1 << t.shift) < w; ++t.shift) {}
    return t;
  }
  // The reference: gs::sample (TEX1 nearest) of the texel at (u, v) after CLAMP_1's wrap.
  gs::rgba8 sample(std::int32_t u16, std::int32_t v16) const {
    return gs::sample(
        [&](std::int32_t u, std::int32_t v) {
          u = clamp ? std::clamp(u, 0, w - 1) : u & (w - 1);
          v = clamp ? std::clamp(v, 0, h - 1) : v & (h - 1);
          const auto i = static_cast<std::size_t>(v * w + u);
          return gs::rgba8::from_u32(index.empty() ? words[i] : words[index[i]]);
        },
        u16, v16, gs::bilinear_mode::nearest);
  }
};

// Bulk data (frames, textures, the cuts of the runs) from a generator seeded by the property: rapidcheck
// shrinks the seed and the shapes, not each word.
std::vector<std::uint32_t> words(std::mt19937& rng, std::size_t n) {
  std::vector<std::uint32_t> w(n);
  for (std::uint32_t& x : w) x = static_cast<std::uint32_t>(rng());
  return w;
}

texture random_texture(std::mt19937& rng) {
  texture t;
  const int a = *rc::gen::inRange(0, 7);  // at least 4 texels
  t.w = 1 << a, t.h = 1 << *rc::gen::inRange(std::max(0, 2 - a), 7);
  t.clamp = *rc::gen::arbitrary<bool>();
  const auto texels = static_cast<std::size_t>(t.w * t.h);
  if (*rc::gen::arbitrary<bool>()) {
    t.index.resize(texels);
    for (std::uint8_t& i : t.index) i = static_cast<std::uint8_t>(rng());
    t.words = words(rng, 256);
  } else {
    t.words = words(rng, texels);
  }
  return t;
}

std::string failure(const std::string& target, int x, int y, std::uint32_t got, std::uint32_t want) {
  std::ostringstream os;
  os << target << ": pixel (" << x << ", " << y << ") span engine 0x" << std::hex << got << ", scalar 0x" << want;
  return os.str();
}

// One random triangle through span_triangle against the scalar reference; counts the triangles with
// pixels and those the engine took.
void check_triangle(const std::string& target, int& cases, int& drawn) {
  gs::model_options o = random_options();
  o.uv_convert = *rc::gen::element(gs::uv_convert_mode::floor, gs::uv_convert_mode::floor_1_64);
  o.setup = *rc::gen::element(gs::gouraud_setup::per_pixel_floor, gs::gouraud_setup::per_pixel_floor,
                              gs::gouraud_setup::plane_steps, gs::gouraud_setup::per_pixel);
  const gs::gs_registers regs = random_registers();
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  const texture tex = random_texture(rng);
  const bool textured = *rc::gen::inRange(0, 5) != 0;
  std::array<gs::xy124, 3> v{};
  for (gs::xy124& p : v) p = {*rc::gen::inRange(-64, 16 * width + 64), *rc::gen::inRange(-64, 16 * height + 64)};
  const gs::triangle_setup t = gs::setup_triangle(v);
  const bool flat = *rc::gen::inRange(0, 3) == 0;
  std::array<gs::rgba8, 3> c{};
  for (gs::rgba8& k : c) k = gs::rgba8::from_u32(flat ? 0x80FFFFFFu : *rc::gen::arbitrary<std::uint32_t>());
  const int reach = 16 * std::max(tex.w, tex.h) * *rc::gen::inRange(1, 5);
  std::array<std::array<std::int32_t, 2>, 3> uv{};
  for (auto& p : uv) p = {*rc::gen::inRange(-reach, reach), *rc::gen::inRange(-reach, reach)};
  const gs::triangle_attributes a =
      gs::setup_attributes(t, c, uv, *rc::gen::inRange(-8, 9), *rc::gen::inRange(-8, 9), o.setup, gs::uv_rule_of(o));
  // The rows as runs, each cut where a random pixel is left out.
  std::vector<span_run> runs;
  int x0 = width, x1 = 0, y0 = height, y1 = 0;
  gs::rasterise_spans(t, {0, 0, width, height}, [&](int y, int xa, int xb) {
    for (int x = xa; x < xb; ++x) {
      if (rng() % 8 == 0) continue;
      if (!runs.empty() && runs.back().y == y && runs.back().x0 + runs.back().n == x) {
        ++runs.back().n;
      } else {
        runs.push_back({x, y, 1});
      }
      x0 = std::min(x0, x), x1 = std::max(x1, x + 1), y0 = std::min(y0, y), y1 = std::max(y1, y + 1);
    }
  });
  RC_PRE(!runs.empty());
  ++cases;
  if (!span_applies(a, x0, y0, x1, y1)) return;
  ++drawn;
  std::vector<std::uint32_t> frame = words(rng, width * height), want = frame;
  for (const span_run& r : runs)
    for (int x = r.x0; x < r.x0 + r.n; ++x) {
      std::uint32_t& w = want[static_cast<std::size_t>(r.y * width + x)];
      const gs::rgba8 texel = textured ? tex.sample(a.u.at(x, r.y), a.v.at(x, r.y)) : gs::rgba8{};
      w = gs::pixel_pipeline(regs,
                             {a.colour_at(x, r.y), texel, w, static_cast<unsigned>(x), static_cast<unsigned>(r.y)}, o)
              .out;
    }
  span_triangle(regs, o, a, textured ? tex.lanes() : nearest_texture{}, runs.data(), runs.size(), frame.data(), width);
  for (std::size_t i = 0; i < frame.size(); ++i)
    if (frame[i] != want[i])
      RC_FAIL(failure(target, static_cast<int>(i % width), static_cast<int>(i / width), frame[i], want[i]));
}

TEST(SpanDraw, TrianglesEqualTheScalarChainOnEveryTarget) {
  for_each_target([](const std::string& target) {
    int drawn = 0, cases = 0;
    EXPECT_TRUE(rc::check("span_triangle on " + target, [&] { check_triangle(target, cases, drawn); }));
    EXPECT_GT(drawn, cases / 2) << target << ": most random triangles are in the engine's domain";
  });
}

TEST(SpanDraw, RectanglesWiderThanAChunkAreLeftToTheWalker) {
  const std::array<gs::xy124, 3> v{{{0, 0}, {16 * 4000, 0}, {0, 16 * 8}}};
  const gs::triangle_attributes a =
      gs::setup_attributes(gs::setup_triangle(v), {}, {}, 0, 0, gs::gouraud_setup::per_pixel_floor, {});
  EXPECT_TRUE(span_applies(a, 0, 0, max_run, 8));
  EXPECT_FALSE(span_applies(a, 0, 0, max_run + 1, 8));
}

// A sprite row (span_row) and a channel row (span_channel_row) against the scalar chain.
void check_rows(const std::string& target) {
  const gs::model_options o = random_options();
  const gs::gs_registers regs = random_registers();
  const gs::fragment_colour cf = gs::fragment_colour::flat(gs::rgba8::from_u32(*rc::gen::arbitrary<std::uint32_t>()));
  const int y = *rc::gen::inRange(0, height), x0 = *rc::gen::inRange(0, width);
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, width - x0 + 1));
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  std::vector<std::uint32_t> frame = words(rng, width * height), src = words(rng, width * height);
  const std::vector<std::uint32_t> texels = words(rng, n), clut = words(rng, 256);
  const unsigned channel = *rc::gen::inRange(0u, 4u);
  const bool own = *rc::gen::arbitrary<bool>();  // the channel read from the row it writes
  std::vector<std::uint32_t> want = frame, want_channel = frame;
  const std::size_t at = static_cast<std::size_t>(y * width + x0);
  for (std::size_t k = 0; k < n; ++k) {
    const auto x = static_cast<unsigned>(x0) + static_cast<unsigned>(k);
    const gs::rgba8 t = gs::rgba8::from_u32(texels[k]);
    want[at + k] = gs::pixel_pipeline(regs, {cf, t, want[at + k], x, static_cast<unsigned>(y)}, o).out;
    const std::uint32_t s = own ? want_channel[at + k] : src[at + k];
    const gs::rgba8 ct = gs::rgba8::from_u32(clut[(s >> (8 * channel)) & 0xFFu]);
    want_channel[at + k] = gs::pixel_pipeline(regs, {cf, ct, want_channel[at + k], x, static_cast<unsigned>(y)}, o).out;
  }
  std::vector<std::uint32_t> rows = frame, channel_rows = frame;
  span_row(regs, o, cf, texels.data(), rows.data() + at, x0, y, n);
  span_channel_row(regs, o, cf, own ? channel_rows.data() + at : src.data() + at, channel, clut.data(),
                   channel_rows.data() + at, x0, y, n);
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const int px = static_cast<int>(i % width), py = static_cast<int>(i / width);
    if (rows[i] != want[i]) RC_FAIL("span_row, " + failure(target, px, py, rows[i], want[i]));
    if (channel_rows[i] != want_channel[i])
      RC_FAIL("span_channel_row, " + failure(target, px, py, channel_rows[i], want_channel[i]));
  }
}

TEST(SpanDraw, SpriteRowsEqualTheScalarChainOnEveryTarget) {
  for_each_target([](const std::string& t) { EXPECT_TRUE(rc::check("rows on " + t, [&] { check_rows(t); })); });
}

}  // namespace
}  // namespace gsdot3::simd::test
