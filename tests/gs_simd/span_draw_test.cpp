// The span engine (gs_simd/span_draw.hpp) against the scalar reference, on every SIMD target this CPU
// supports (rapidcheck): a random triangle's attributes (gs::setup_attributes under random model
// options: the UV plane exact and lifted or not, the colour flat, per_pixel_floor or another set-up),
// its rows as runs cut at random (the renderer's runs skip the pixels the depth test drops), a random
// texture (PSMT8 through a CLUT, or 32-bit texels; REPEAT or CLAMP; 2×2 to 64×64) and random
// registers. Every pixel of every run must equal gs::pixel_pipeline(regs, {colour_at, gs::sample of the
// texture at (u.at, v.at), old word, x, y}).out; the frame outside the runs must not change. The sprite
// rows (span_row, span_channel_row) and the memory path's fetched pixels (span_fetched) likewise
// against the scalar chain; the engine on a frame in a local memory through its address tables.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "gs_arith/bilinear.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/span_raster.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_simd/span_draw.hpp"
#include "lanes.hpp"
#include "random_state.hpp"

namespace gsdot3::simd::test {
namespace {

constexpr int width = 72, height = 40;  // the frame: odd-sized rows, wider than four AVX-512 vectors
constexpr std::size_t memory_words = gs::mem::memory_bytes / 4;

struct texture {
  int w = 0, h = 0;
  bool clamp = false;
  std::vector<std::uint8_t> index;   // PSMT8, or empty
  std::vector<std::uint32_t> words;  // the CLUT (256) with index, else the texels
  // Placed in a local memory (the memory path): PSMT8 or PSMCT32 at TBP0 = bp through `at`.
  std::optional<gs::mem::texel_addresses> at;
  const gs::mem::local_memory* memory = nullptr;
  std::uint32_t bp = 0;
  nearest_texture lanes() const {
    nearest_texture t;
    if (memory != nullptr) {
      if (!index.empty()) t.words = words.data();
      t.memory = memory->words(), t.address = at->table(), t.base = bp * gs::mem::block_bytes;
      t.mask = gs::mem::memory_bytes - 1;
    } else {
      (index.empty() ? t.texels : t.words) = words.data();
      if (!index.empty()) t.index = index.data();
    }
    t.wmask = w - 1, t.hmask = h - 1, t.clamp = clamp;
    for (t.shift = 0; (1 << t.shift) < w; ++t.shift) {}
    return t;
  }
  // The reference: gs::sample (TEX1 nearest) of the texel at (u, v) after CLAMP_1's wrap, from the host
  // arrays or read from the memory by texel_addresses::read.
  gs::rgba8 sample(std::int32_t u16, std::int32_t v16) const {
    return gs::sample(
        [&](std::int32_t u, std::int32_t v) {
          u = clamp ? std::clamp(u, 0, w - 1) : u & (w - 1);
          v = clamp ? std::clamp(v, 0, h - 1) : v & (h - 1);
          if (memory != nullptr) {
            const std::uint32_t t = at->read(*memory, static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v), bp);
            return gs::rgba8::from_u32(index.empty() ? t : words[t]);
          }
          const auto i = static_cast<std::size_t>(v * w + u);
          return gs::rgba8::from_u32(index.empty() ? words[i] : words[index[i]]);
        },
        u16, v16, gs::bilinear_mode::nearest);
  }
  // Writes the texels into `m` at a random TBP0 (PSMT8 or PSMCT32, TBW = the width in 64-texel units).
  void place(gs::mem::local_memory& m, std::uint32_t block) {
    const gs::mem::psm p = index.empty() ? gs::mem::psm::PSMCT32 : gs::mem::psm::PSMT8;
    at.emplace(p, std::max<std::uint32_t>(1, static_cast<std::uint32_t>(w) / 64), w, h);
    memory = &m, bp = block;
    for (std::uint32_t v = 0; v < static_cast<std::uint32_t>(h); ++v)
      for (std::uint32_t u = 0; u < static_cast<std::uint32_t>(w); ++u) {
        const std::size_t i = v * static_cast<std::uint32_t>(w) + u;
        const std::uint32_t b = at->byte(u, v, bp);
        if (index.empty()) {
          m.words()[b / 4] = words[i];
        } else {
          m.set_byte(b, index[i]);
        }
      }
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
  texture tex = random_texture(rng);
  const bool textured = *rc::gen::inRange(0, 5) != 0;
  // The memory path: the frame a PSMCT32 buffer (or PSMZ32) of one local memory at a random FBP and
  // FBW (through row_column_address), the texture placed in another.
  const bool in_memory = *rc::gen::arbitrary<bool>();
  static gs::mem::local_memory frame_memory, texture_memory;
  if (in_memory) tex.place(texture_memory, *rc::gen::inRange(0u, 16384u));
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
  std::vector<std::uint32_t> frame = words(rng, width * height);
  const gs::mem::layout layout = *rc::gen::element(gs::mem::layout::ct32, gs::mem::layout::z32);
  const gs::mem::row_column_address address(layout, *rc::gen::inRange(0u, 16384u), *rc::gen::inRange(2u, 6u), width,
                                            height);
  auto unit = [&](int x, int y) { return address.unit(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)); };
  if (in_memory) {
    std::fill(frame_memory.words(), frame_memory.words() + memory_words, 0u);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) frame_memory.words()[unit(x, y)] = frame[static_cast<std::size_t>(y * width + x)];
  }
  std::vector<std::uint32_t> want = frame;
  for (const span_run& r : runs)
    for (int x = r.x0; x < r.x0 + r.n; ++x) {
      std::uint32_t& w = want[static_cast<std::size_t>(r.y * width + x)];
      const gs::rgba8 texel = textured ? tex.sample(a.u.at(x, r.y), a.v.at(x, r.y)) : gs::rgba8{};
      w = gs::pixel_pipeline(regs,
                             {a.colour_at(x, r.y), texel, w, static_cast<unsigned>(x), static_cast<unsigned>(r.y)}, o)
              .out;
    }
  const nearest_texture lanes = textured ? tex.lanes() : nearest_texture{};
  if (!in_memory) {
    span_triangle(regs, o, a, lanes, runs.data(), runs.size(), {frame.data(), width});
  } else {
    static std::vector<std::uint32_t> before, after;  // kept between cases (4 MiB each)
    before.assign(frame_memory.words(), frame_memory.words() + memory_words);
    span_triangle(regs, o, a, lanes, runs.data(), runs.size(),
                  {frame_memory.words(), 0, address.rows(), address.columns(), address.mask()});
    // The frame read back through the address function; every other word of the memory unchanged.
    after.assign(frame_memory.words(), frame_memory.words() + memory_words);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        frame[static_cast<std::size_t>(y * width + x)] = after[unit(x, y)];
        after[unit(x, y)] = before[unit(x, y)];
      }
    RC_ASSERT(after == before);
  }
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

// The memory path's fetched pixels (span_fetched) against the scalar chain pixel by pixel in order:
// up to 300 pixels with distinct words of a small memory from a random base, each reading a byte of
// its own word or of a word no pixel writes, given as random bases plus offsets.
void check_fetched(const std::string& target) {
  const gs::model_options o = random_options();
  const gs::gs_registers regs = random_registers();
  const gs::fragment_colour cf = gs::fragment_colour::flat(gs::rgba8::from_u32(*rc::gen::arbitrary<std::uint32_t>()));
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  std::vector<std::uint32_t> memory = words(rng, 2048), want = memory;
  const std::vector<std::uint32_t> clut = words(rng, 256);
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(0, 300));
  const std::uint32_t word_base = *rc::gen::inRange(0u, 64u), read_base = 4 * *rc::gen::inRange(0u, word_base + 1);
  const int x0 = *rc::gen::inRange(0, 2048), y0 = *rc::gen::inRange(0, 2048);
  std::vector<std::uint32_t> word(512);  // the written words' offsets: a random n of the first 512
  for (std::uint32_t i = 0; i < 512; ++i) word[i] = i;
  std::shuffle(word.begin(), word.end(), rng);
  word.resize(n);
  std::vector<std::uint32_t> read(n);
  std::vector<std::int32_t> x(n), y(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t w = rng() % 2 == 0 ? word_base + word[k] : 640 + static_cast<std::uint32_t>(rng() % 1024);
    read[k] = 4 * w + static_cast<std::uint32_t>(rng() % 4) - read_base;
    x[k] = static_cast<std::int32_t>(rng() % 2048), y[k] = static_cast<std::int32_t>(rng() % 2048);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t b = read_base + read[k], byte = (want[b / 4] >> (8 * (b % 4))) & 0xFFu;
    std::uint32_t& w = want[word_base + word[k]];
    w = gs::pixel_pipeline(regs,
                           {cf, gs::rgba8::from_u32(clut[byte]), w, static_cast<unsigned>(x0 + x[k]),
                            static_cast<unsigned>(y0 + y[k])},
                           o)
            .out;
  }
  span_fetched(regs, o, cf, memory.data(), read_base, read.data(), clut.data(), word_base, word.data(), x0, y0,
               x.data(), y.data(), n);
  for (std::size_t i = 0; i < memory.size(); ++i)
    if (memory[i] != want[i])
      RC_FAIL("span_fetched, " + failure(target, static_cast<int>(i), 0, memory[i], want[i]) + " (word i)");
}

TEST(SpanDraw, FetchedPixelsEqualTheScalarChainOnEveryTarget) {
  for_each_target([](const std::string& t) { EXPECT_TRUE(rc::check("fetched on " + t, [&] { check_fetched(t); })); });
}

TEST(SpanDraw, SpriteRowsEqualTheScalarChainOnEveryTarget) {
  for_each_target([](const std::string& t) { EXPECT_TRUE(rc::check("rows on " + t, [&] { check_rows(t); })); });
}

}  // namespace
}  // namespace gsdot3::simd::test
