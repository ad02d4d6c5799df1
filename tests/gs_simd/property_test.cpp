// The SIMD units whose domains exceed 2^32 (the texture function, frame read / pack / mask, FBA,
// the FBMSK merge, the blend of whole colours) and the whole pixel chain against the scalar gs_arith
// units on random inputs (rapidcheck), on every SIMD target this CPU supports.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <sstream>

#include "lanes.hpp"
#include "random_state.hpp"

namespace gsdot3::simd::test {
namespace {

constexpr std::size_t n = 64;

std::int32_t word() { return static_cast<std::int32_t>(*rc::gen::arbitrary<std::uint32_t>()); }
gs::rgba8 rgba(std::int32_t w) { return gs::rgba8::from_u32(static_cast<std::uint32_t>(w)); }
gs::fragment_colour cf_of(const block& b, std::size_t i) {
  auto c = [&](std::size_t k) { return gs::gouraud_channel::from_wrapped(b.in[k][i]); };
  return {c(1), c(2), c(3), c(4)};
}

// One random call of every word-sized unit, compared lane by lane.
void check_units(const std::string& target) {
  const gs::gs_registers r = random_registers();
  const gs::model_options o = random_options();
  block b(n);
  for (std::size_t i = 0; i < n; ++i) {
    b.in[0][i] = word();
    for (std::size_t k = 1; k < 4; ++k) b.in[k][i] = *rc::gen::inRange(0, 1 << 15);
    b.in[4][i] = *rc::gen::inRange(0, 1 << 15);
  }
  const gs::frame_psm psm = r.FRAME_1.PSM;
  std::size_t wrong = 0;
  auto run = [&](unit u, std::size_t outputs, const reference& ref, const char* what) {
    unit_call c{u};
    c.regs = r, c.options = o;
    b.run(c);
    wrong += compare(b, outputs, ref, std::string(what) + " on " + target);
  };
  auto u32 = [](std::uint32_t v) { return static_cast<std::int32_t>(v); };
  run(
      unit::texture_function, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::texture_function(r.TEX0_1.TFX, r.TEX0_1.TCC, rgba(k.in[0][i]), cf_of(k, i), o).to_u32())};
      },
      "texture_function");
  run(
      unit::texture_off, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::texture_off(cf_of(k, i)).to_u32())};
      },
      "texture_off");
  run(
      unit::frame_read, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::frame_read(psm, static_cast<std::uint32_t>(k.in[0][i])).to_u32())};
      },
      "frame_read");
  run(
      unit::apply_fba, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::apply_fba(rgba(k.in[0][i]), r.FBA_1.FBA, psm).to_u32())};
      },
      "apply_fba");
  run(
      unit::frame_pack, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::frame_pack(psm, rgba(k.in[0][i])))};
      },
      "frame_pack");
  run(
      unit::frame_mask, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        return {u32(gs::frame_mask(psm, static_cast<std::uint32_t>(k.in[0][i])))};
      },
      "frame_mask");
  for (std::size_t i = 0; i < n; ++i) b.in[1][i] = word(), b.in[2][i] = word();
  run(
      unit::masked_merge, 1,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        auto w = [&](std::size_t c) { return static_cast<std::uint32_t>(k.in[c][i]); };
        return {u32(gs::masked_merge(w(0), w(1), w(2)))};
      },
      "masked_merge");
  run(
      unit::alpha_blend, 3,
      [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
        const gs::rgb_wide v = gs::alpha_blend(r.ALPHA_1, rgba(k.in[0][i]), rgba(k.in[1][i]), o);
        return {v.r.value(), v.g.value(), v.b.value()};
      },
      "alpha_blend");
  RC_ASSERT(wrong == 0u);
}

// The whole chain: gs_simd::pixel_pipeline against gs::pixel_pipeline, n random pixels per batch.
void check_pipeline(const std::string& target) {
  const gs::gs_registers r = random_registers();
  const gs::model_options o = random_options();
  pixel_batch b;
  b.n = static_cast<std::size_t>(*rc::gen::inRange(1, static_cast<int>(pixel_batch::capacity) + 1));
  const bool b16 = gs::bits_of(r.FRAME_1.PSM) == gs::pixel_bits::b16;
  for (std::size_t i = 0; i < b.n; ++i) {
    b.texel[i] = *rc::gen::arbitrary<std::uint32_t>();
    for (auto& c : b.cf) c[i] = static_cast<std::uint32_t>(*rc::gen::inRange(0, 1 << 15));
    b.dst[i] = *rc::gen::arbitrary<std::uint32_t>() & (b16 ? 0xFFFFu : 0xFFFFFFFFu);
    b.x[i] = static_cast<std::uint32_t>(*rc::gen::inRange(0, 2048));
    b.y[i] = static_cast<std::uint32_t>(*rc::gen::inRange(0, 2048));
  }
  pixel_pipeline(r, o, b);
  for (std::size_t i = 0; i < b.n; ++i) {
    auto ch = [&](std::size_t k) { return gs::gouraud_channel::from_wrapped(static_cast<int>(b.cf[k][i])); };
    const gs::pixel_input in{{ch(0), ch(1), ch(2), ch(3)}, gs::rgba8::from_u32(b.texel[i]), b.dst[i], b.x[i], b.y[i]};
    const std::uint32_t expected = gs::pixel_pipeline(r, in, o).out;
    if (b.out[i] != expected) {
      std::ostringstream os;
      os << target << ": lane " << i << std::hex << " texel 0x" << b.texel[i] << " dst 0x" << b.dst[i] << " SIMD 0x"
         << b.out[i] << ", scalar 0x" << expected;
      RC_FAIL(os.str());
    }
  }
}

TEST(SimdProperty, EveryTargetIsCompiledAndOneIsChosen) {
  const std::vector<target> ts = available_targets();
  ASSERT_FALSE(ts.empty());
  EXPECT_EQ(current_target(), ts.front().name);
}

TEST(SimdProperty, UnitsEqualTheScalarUnitsOnEveryTarget) {
  for_each_target([](const std::string& t) { EXPECT_TRUE(rc::check("units on " + t, [&] { check_units(t); })); });
}

TEST(SimdProperty, PixelPipelineEqualsTheScalarChainOnEveryTarget) {
  for_each_target(
      [](const std::string& t) { EXPECT_TRUE(rc::check("pixel_pipeline on " + t, [&] { check_pipeline(t); })); });
}

}  // namespace
}  // namespace gsdot3::simd::test
