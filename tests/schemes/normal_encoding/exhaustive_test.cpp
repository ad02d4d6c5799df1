// The per-code sweep (every 2×8 code of every two-channel method, 65 536 each) against integer
// counts, and the worst-case table at 2×10 and 2×12 (printed: the README's table) checked against
// 2^21 area-uniform directions. Size: 13 methods × 2^16 codes; cells at 10 and 12 bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <tuple>

#include "normal_encoding/cells.hpp"
#include "normal_encoding/sampling.hpp"

namespace ne = gsdot3::normal_encoding;

namespace {
constexpr double deg = 180 / std::numbers::pi;
// Codes whose centre (2i − 255, 2j − 255)/255 lies in the unit disc, in integers.
int codes_in_disc() {
  int n = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j)
      if ((2 * i - 255) * (2 * i - 255) + (2 * j - 255) * (2 * j - 255) <= 255 * 255) ++n;
  return n;
}
// Distinct decoded directions, components rounded to 1e-9 (exact doubles differ by ulps where the
// mapping identifies codes, e.g. octahedral's folded border).
std::size_t distinct_directions(const ne::method& m) {
  std::set<std::tuple<long long, long long, long long>> s;
  for (std::uint32_t i = 0; i < 256; ++i)
    for (std::uint32_t j = 0; j < 256; ++j) {
      const ne::vec3 d = m.decode({{i, j, 0}}, 8);
      if (!ne::finite(d)) continue;
      const ne::vec3 u = ne::normalize(d);
      s.insert({std::llround(u.x * 1e9), std::llround(u.y * 1e9), std::llround(u.z * 1e9)});
    }
  return s.size();
}
}  // namespace

TEST(NormalEncodingExhaustive, EveryCodeAt2x8) {
  const int inside = codes_in_disc();
  for (auto name : {"xy", "spheremap", "cryengine3", "lambert", "view-space"}) {
    const auto& m = ne::method_named(name);
    int nan = 0;
    for (std::uint32_t i = 0; i < 256; ++i)
      for (std::uint32_t j = 0; j < 256; ++j)
        if (!ne::finite(m.decode({{i, j, 0}}, 8))) ++nan;
    EXPECT_EQ(nan, 65536 - inside) << name;  // NaN exactly outside the disc (sqrt of a negative)
    EXPECT_EQ(distinct_directions(m), static_cast<std::size_t>(inside)) << name;
  }
  // Octahedral: 254² interior codes are distinct; each border side's 256 codes pair up (u = ±1 with
  // v and −v fold to one point), 128 directions per side, and the 4 corners are all (0, 0, −1).
  EXPECT_EQ(distinct_directions(ne::method_named("octahedral")), 254u * 254u + 4u * 128u - 3u);
  // Spherical: the rows z = ±1 collapse to the poles, and φ = −π (i = 0) equals φ = π (i = 255).
  EXPECT_EQ(distinct_directions(ne::method_named("spherical")), 254u * 255u + 2u);
  // Stereographic is one-to-one on all codes.
  EXPECT_EQ(distinct_directions(ne::method_named("stereographic")), 65536u);
  // Every code of octahedral (unorm) with a unique direction encodes back to itself.
  const auto& oct = ne::method_named("octahedral");
  int back = 0;
  for (std::uint32_t i = 1; i < 255; ++i)
    for (std::uint32_t j = 1; j < 255; ++j)
      if (oct.encode(oct.decode({{i, j, 0}}, 8), 8) == ne::code{{i, j, 0}}) ++back;
  EXPECT_EQ(back, 254 * 254);
}

TEST(NormalEncodingExhaustive, WorstCaseTableAt10And12Bits) {
  constexpr std::uint64_t samples = std::uint64_t{1} << 21;
  std::printf("%-20s %5s %14s %14s %14s %10s  witness n (hex)\n", "method", "bits", "sup_deg", "upper_deg",
              "sampled_deg", "nan_cells");
  for (int bits : {10, 12}) {  // 8 bits: the catalogue's normal-encoding.worst-case
    for (const auto& m : ne::methods()) {
      if (m.only_8_bits && bits != 8) continue;
      const auto& cm = m.id == ne::method_id::octahedral_precise ? ne::method_of(ne::method_id::octahedral) : m;
      const auto w = ne::cell_worst_case(cm, bits, 2);
      double sampled = 0;
      for (std::uint64_t k = 0; k < samples; ++k) {
        const ne::vec3 p = ne::fibonacci_point(k, samples);
        if (m.front_hemisphere && p.z < 0) continue;
        const ne::vec3 d = m.decode(m.encode(p, bits), bits);
        if (ne::finite(d)) sampled = std::max(sampled, ne::angle(d, p) * deg);
      }
      EXPECT_LE(sampled, w.upper_deg + 1e-9) << m.name << " " << bits;
      // liamtyler.github.io "octahedral analysis": 12+12 bits, 10^6 random directions, max 0.0586°.
      if (m.id == ne::method_id::octahedral && bits == 12) { EXPECT_GE(w.sup_deg, 0.0586); }
      std::printf("%-20s %5d %14.9f %14.9f %14.9f %10llu  (%a, %a, %a)\n", std::string(m.name).c_str(), bits, w.sup_deg,
                  w.upper_deg, sampled, static_cast<unsigned long long>(w.nonfinite_cells), w.witness.x, w.witness.y,
                  w.witness.z);
    }
  }
}
