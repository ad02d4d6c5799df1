// tests/pipeline/resolved_fetch_test.cpp — nearest_host_fetch (gs_pass.hpp), the value path's resolved
// fetch, against the readable texture_ref::sample, for CLUT indices and 32-bit texels under REPEAT and
// CLAMP: every 12.4 coordinate pair over four repeats of a small texture in each direction (negative
// coordinates included), and random pairs on larger ones. And the cases it must not take.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pipeline/gs_pass.hpp"

namespace gsdot3::pipeline {
namespace {

struct texture {
  std::vector<std::uint8_t> index;
  std::vector<std::uint32_t> words;
  gs::clut_buffer clut{};
};

texture random_texture(int w, int h, std::mt19937& rng) {
  texture t;
  t.index.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  t.words.resize(t.index.size());
  for (auto& i : t.index) i = static_cast<std::uint8_t>(rng());
  for (auto& x : t.words) x = static_cast<std::uint32_t>(rng());
  for (auto& e : t.clut) e = gs::rgba8::from_u32(static_cast<std::uint32_t>(rng()));
  return t;
}
// The four kinds: CLUT indices or 32-bit texels, REPEAT or CLAMP.
std::vector<texture_ref> kinds(const texture& t, int w, int h) {
  std::vector<texture_ref> out;
  for (bool indexed : {true, false})
    for (bool clamp : {false, true}) {
      texture_ref r;
      r.width = w, r.height = h, r.clamp = clamp;
      if (indexed)
        r.index = t.index.data(), r.clut = &t.clut;
      else
        r.texels = t.words.data();
      out.push_back(r);
    }
  return out;
}
std::string name(const texture_ref& r) {
  return std::to_string(r.width) + "x" + std::to_string(r.height) + (r.index != nullptr ? " CLUT" : " 32-bit") +
         (r.clamp ? " CLAMP" : " REPEAT");
}

TEST(ResolvedFetch, EqualsSampleOverFourRepeatsOfASmallTexture) {
  std::mt19937 rng(7);
  const int w = 8, h = 16;
  const texture t = random_texture(w, h, rng);
  for (const texture_ref& ref : kinds(t, w, h)) {
    ASSERT_TRUE(nearest_host_fetch::applies(ref));
    const nearest_host_fetch fast(ref);
    long checked = 0, differing = 0;
    for (std::int32_t v16 = -2 * 16 * h; v16 < 2 * 16 * h; ++v16)
      for (std::int32_t u16 = -2 * 16 * w; u16 < 2 * 16 * w; ++u16, ++checked)
        if (fast.texel(u16, v16) != ref.sample(u16, v16).to_u32() && differing++ < 3)
          ADD_FAILURE() << name(ref) << ": u16 " << u16 << ", v16 " << v16;
    EXPECT_EQ(checked, 4L * 16 * w * 4 * 16 * h);
    EXPECT_EQ(differing, 0) << name(ref);
  }
}

TEST(ResolvedFetch, EqualsSampleOnRandomCoordinatesOfLargerTextures) {
  std::mt19937 rng(11);
  for (const auto& [w, h] : {std::pair{256, 64}, std::pair{64, 1024}, std::pair{1024, 1024}}) {
    const texture t = random_texture(w, h, rng);
    for (const texture_ref& ref : kinds(t, w, h)) {
      const nearest_host_fetch fast(ref);
      std::uniform_int_distribution<std::int32_t> coordinate(-(1 << 19), 1 << 19);  // beyond UV's 14.4 range
      long differing = 0;
      for (int k = 0; k < 100000; ++k) {
        const std::int32_t u16 = coordinate(rng), v16 = coordinate(rng);
        if (fast.texel(u16, v16) != ref.sample(u16, v16).to_u32() && differing++ < 3)
          ADD_FAILURE() << name(ref) << ": u16 " << u16 << ", v16 " << v16;
      }
      EXPECT_EQ(differing, 0) << name(ref);
    }
  }
}

TEST(ResolvedFetch, TakesNeitherFilteringNorLocalMemory) {
  std::mt19937 rng(3);
  const texture t = random_texture(8, 8, rng);
  for (texture_ref r : kinds(t, 8, 8)) {
    EXPECT_TRUE(nearest_host_fetch::applies(r));
    texture_ref linear = r, memory = r;
    linear.filter = gs::bilinear_mode::lerp16_4;
    const gs::mem::local_memory m;
    memory.memory = &m;
    EXPECT_FALSE(nearest_host_fetch::applies(linear)) << name(r);
    EXPECT_FALSE(nearest_host_fetch::applies(memory)) << name(r);
  }
}

}  // namespace
}  // namespace gsdot3::pipeline
