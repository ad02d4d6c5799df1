// gs_arith_perspective — S, T, Q at a pixel and their conversion to 12.4 texels (gs_arith/perspective.hpp)
// against exact integer arithmetic: a float is m·2^e with an integer m, so S/Q's float32 quotient scaled
// by 2^TW·16 (or ·65536) is an exact binary fraction whose truncation and floor are integer shifts; and
// a plane's value at a pixel is the rational Σ E_i·S_i / area2, compared in 128-bit integers with the
// float32 the model returns (within one unit in its last place; equal where the plane is constant).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "gs_arith/perspective.hpp"

namespace {

__extension__ typedef __int128 i128;

// x = m·2^e exactly, m a signed integer of at most 24 bits (0 for x = 0).
void split(float x, std::int64_t& m, int& e) {
  int ex = 0;
  const float f = std::frexp(x, &ex);  // x = f·2^ex, 0.5 <= |f| < 1
  m = static_cast<std::int64_t>(std::ldexp(f, 24));
  e = ex - 24;
}

// floor(m·2^k) and trunc(m·2^k) for an integer |m| < 2^40, by shifts (k < -100: |m·2^k| < 2^-60).
i128 floor_shift(i128 m, int k) {
  if (k < -100) return m < 0 ? -1 : 0;
  return k >= 0 ? m * (i128{1} << k) : (m >= 0 ? m >> -k : -((-m + (i128{1} << -k) - 1) >> -k));
}
i128 trunc_shift(i128 m, int k) {
  if (k < -100) return 0;
  return k >= 0 ? m * (i128{1} << k) : (m >= 0 ? m >> -k : -((-m) >> -k));
}

std::int32_t as_int32_or_indefinite(i128 v) {
  if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
    return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(v);
}

// The reference conversion: f = the float32 quotient (the one operation both sides share: IEEE
// division), then range and conversion written with integers.
std::int32_t reference_texel(float s, float q, unsigned size_log2, const gs::model_options& o) {
  float f = s / q;
  if (o.stq_range == gs::stq_range_mode::saturate_2047) f = std::fmax(-2047.0f, std::fmin(2047.0f, f));
  std::int64_t m = 0;
  int e = 0;
  split(f, m, e);
  const int k = e + static_cast<int>(size_log2);  // texels = m·2^k, |m| < 2^24
  constexpr std::int32_t indefinite = std::numeric_limits<std::int32_t>::min();
  if (m != 0 && k > 40)  // |texels| >= 2^40: outside int32 at any scale here
    return o.stq_convert == gs::stq_convert_mode::trunc_16_16 ? indefinite / 4096 : indefinite;
  const int j = k + 4;  // sixteenths = m·2^j
  switch (o.stq_convert) {
    case gs::stq_convert_mode::truncate: return as_int32_or_indefinite(trunc_shift(m, j));
    case gs::stq_convert_mode::floor_1_64:  // floor(m·2^j + 2^-6)
      if (j >= 0) return as_int32_or_indefinite(floor_shift(m, j));
      if (j < -80) return 0;  // 2^-6 plus a value below 2^-56 in magnitude
      if (j <= -6) return as_int32_or_indefinite(floor_shift(m + (i128{1} << (-j - 6)), j));
      return as_int32_or_indefinite(floor_shift(m * (i128{1} << (j + 6)) + 1, -6));
    case gs::stq_convert_mode::trunc_16_16: {
      const std::int32_t w = as_int32_or_indefinite(trunc_shift(m, k + 16));
      return static_cast<std::int32_t>(floor_shift(w, -12));
    }
  }
  return 0;
}

gs::model_options with(gs::stq_range_mode r, gs::stq_convert_mode c) {
  gs::model_options o;
  o.stq_range = r;
  o.stq_convert = c;
  return o;
}

constexpr gs::stq_range_mode ranges[] = {gs::stq_range_mode::saturate_2047, gs::stq_range_mode::x86_int32};
constexpr gs::stq_convert_mode converts[] = {gs::stq_convert_mode::truncate, gs::stq_convert_mode::floor_1_64,
                                             gs::stq_convert_mode::trunc_16_16};

// Quotients near every sixteenth of a texel (a few ulps either side), at ±, over sizes 1..1024, and
// random S, Q of every magnitude, including beyond 2047 and beyond int32 at 16.16.
TEST(StqTexel, EqualsTheIntegerReferenceForEveryOption) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<float> mant(1.0f, 2.0f);
  std::uniform_int_distribution<int> expo(-30, 40), tw(0, 10), coin(0, 1);
  int checked = 0, negative_differs = 0;
  for (const auto r : ranges)
    for (const auto c : converts) {
      const gs::model_options o = with(r, c);
      for (unsigned size = 0; size <= 10; ++size)
        for (int sixteenth = -80; sixteenth <= 80; ++sixteenth) {
          const float centre = std::ldexp(static_cast<float>(sixteenth), -4 - static_cast<int>(size));
          float x = centre;
          for (int step = 0; step < 4; ++step) x = std::nextafter(x, -1.0e9f);
          for (int step = 0; step < 9; ++step, x = std::nextafter(x, 1.0e9f)) {
            for (const float q : {1.0f, 0.75f, 3.0f}) {
              const float s = x * q;  // S/Q rounds back to about x
              ASSERT_EQ(gs::stq_texel(s, q, size, o), reference_texel(s, q, size, o))
                  << s << " / " << q << " size 2^" << size << " " << static_cast<int>(r) << static_cast<int>(c);
              ++checked;
            }
          }
        }
      for (int i = 0; i < 200000; ++i) {
        const float s = (coin(rng) ? -1.0f : 1.0f) * std::ldexp(mant(rng), expo(rng));
        const float q = (coin(rng) ? -1.0f : 1.0f) * std::ldexp(mant(rng), expo(rng) / 2);
        const auto size = static_cast<unsigned>(tw(rng));
        ASSERT_EQ(gs::stq_texel(s, q, size, o), reference_texel(s, q, size, o)) << s << " / " << q << " 2^" << size;
        ++checked;
      }
    }
  // The values told apart where the sources say they differ: just below zero, a sixteenth's
  // truncation rounds up to 0, the floors down to -1.
  const float just_below = -std::ldexp(1.0f, -8);  // a sixteenth of a sixteenth below 0
  negative_differs += gs::stq_texel(just_below, 1.0f, 0, with(ranges[0], converts[0])) == 0;
  negative_differs += gs::stq_texel(just_below, 1.0f, 0, with(ranges[0], converts[1])) == -1;
  negative_differs += gs::stq_texel(just_below, 1.0f, 0, with(ranges[0], converts[2])) == -1;
  EXPECT_EQ(negative_differs, 3);
  // saturate_2047 keeps 3000 repeats of a 1-texel texture at 2047·16 sixteenths; x86_int32 does not.
  EXPECT_EQ(gs::stq_texel(3000.0f, 1.0f, 0, with(ranges[0], converts[0])), 2047 * 16);
  EXPECT_EQ(gs::stq_texel(3000.0f, 1.0f, 0, with(ranges[1], converts[0])), 3000 * 16);
  EXPECT_EQ(gs::stq_texel(40000.0f, 1.0f, 0, with(ranges[1], converts[2])),
            std::numeric_limits<std::int32_t>::min() >> 12);
  EXPECT_GT(checked, 1000000);
}

// A triangle's S, T, Q at a pixel: within one float32 ulp of the exact rational plane, and exact where
// the attribute is the same at the three vertices.
TEST(StqAt, WithinOneUlpOfTheExactPlane) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pos(-4000, 12000);
  std::uniform_real_distribution<float> val(0.001f, 64.0f);
  std::uniform_int_distribution<int> pix(-50, 800);
  int checked = 0;
  for (int tri = 0; tri < 3000; ++tri) {
    gs::stq_triangle t;
    for (auto& v : t.v) v = {pos(rng), pos(rng)};
    t.area2 = static_cast<std::int64_t>(t.v[1].x - t.v[0].x) * (t.v[2].y - t.v[0].y) -
              static_cast<std::int64_t>(t.v[1].y - t.v[0].y) * (t.v[2].x - t.v[0].x);
    if (t.area2 == 0) continue;
    const float same = val(rng);
    for (auto& a : t.a) a = {val(rng), same, val(rng)};
    for (int k = 0; k < 20; ++k) {
      const int x = pix(rng), y = pix(rng);
      const gs::stq got = gs::stq_at(t, x, y);
      EXPECT_EQ(got.T, same);  // Σ E_i = area2 exactly, so a constant plane is its value
      // Exact: value = Σ E_i·m_i·2^(e_i) / area2; the common exponent is the least e_i.
      for (float gs::stq::*f : {&gs::stq::S, &gs::stq::Q}) {
        std::int64_t m[3], mg = 0;
        int e[3], eg = 0, emin = 1000;
        for (int i = 0; i < 3; ++i) split(t.a[static_cast<std::size_t>(i)].*f, m[i], e[i]), emin = std::min(emin, e[i]);
        split(got.*f, mg, eg);
        const gs::xy124 p{16 * x, 16 * y};
        auto cross = [](gs::xy124 a, gs::xy124 b, gs::xy124 c) {
          return i128{b.x - a.x} * (c.y - a.y) - i128{b.y - a.y} * (c.x - a.x);
        };
        const i128 E[3] = {cross(t.v[1], t.v[2], p), cross(t.v[2], t.v[0], p), cross(t.v[0], t.v[1], p)};
        i128 num = 0;  // the exact value times area2, in units of 2^emin
        for (int i = 0; i < 3; ++i) num += E[i] * m[i] * (i128{1} << (e[i] - emin));
        // |got − exact| <= ulp(got) = 2^eg (24-bit mantissa), in units of 2^emin times area2.
        const int shift = eg - emin;
        ASSERT_GE(shift, -20);
        ASSERT_LE(shift, 60);
        const i128 area = t.area2;
        const i128 got_scaled = shift >= 0 ? i128{mg} * (i128{1} << shift) * area : 0;
        const i128 ulp_scaled = shift >= 0 ? (i128{1} << shift) * (area < 0 ? -area : area) : 0;
        if (shift < 0) continue;  // a value below 2^-20 of the smallest vertex value: not reached here
        const i128 diff = got_scaled - num;
        ASSERT_LE(diff < 0 ? -diff : diff, ulp_scaled) << "triangle " << tri << " pixel " << x << "," << y;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

// The one-sign Q a perspective triangle is drawn with: (−S)/(−Q) converts as S/Q (why parallel-gs's
// sign flip and the others' plain division agree, perspective.hpp).
TEST(StqTexel, NegatingSAndQTogetherChangesNothing) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> v(-100.0f, 100.0f), q(0.01f, 10.0f);
  for (const auto r : ranges)
    for (const auto c : converts)
      for (int i = 0; i < 20000; ++i) {
        const float s = v(rng), qq = q(rng);
        ASSERT_EQ(gs::stq_texel(s, qq, 6, with(r, c)), gs::stq_texel(-s, -qq, 6, with(r, c)));
      }
}

}  // namespace
