// rapidcheck: for random unit n (area-uniform: z uniform in [−1, 1], φ uniform), decode(encode(n))
// is within each method's rounding-cell supremum at 2×8 (and octahedral's at 2×10), or NaN only for
// the methods whose cells reach NaN codes.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "normal_encoding/cells.hpp"

namespace ne = gsdot3::normal_encoding;

namespace {
constexpr double deg = 180 / std::numbers::pi;
const ne::worst_case& bound(const ne::method& m, int bits) {
  static std::map<std::pair<int, int>, ne::worst_case> cache;
  const auto key = std::make_pair(static_cast<int>(m.id), bits);
  auto it = cache.find(key);
  if (it == cache.end()) {
    const auto& cm = m.id == ne::method_id::octahedral_precise ? ne::method_of(ne::method_id::octahedral) : m;
    it = cache.emplace(key, ne::cell_worst_case(cm, bits, 2)).first;
  }
  return it->second;
}
rc::Gen<ne::vec3> unit_normal() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << 40),
                                    rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << 40)),
                      [](std::pair<std::int64_t, std::int64_t> p) {
                        const double z = 2 * std::ldexp(static_cast<double>(p.first), -40) - 1;
                        const double phi = 2 * std::numbers::pi * std::ldexp(static_cast<double>(p.second), -40);
                        const double r = std::sqrt(std::max(0.0, 1 - z * z));
                        return ne::vec3{r * std::cos(phi), r * std::sin(phi), z};
                      });
}
void check(const ne::method& m, int bits, ne::vec3 n) {
  if (m.front_hemisphere && n.z < 0) return;
  const auto& w = bound(m, bits);
  const double a = ne::angle(m.decode(m.encode(n, bits), bits), n) * deg;
  if (std::isnan(a)) {
    RC_ASSERT(w.nonfinite_cells > 0);
  } else {
    RC_ASSERT(a <= w.upper_deg + 1e-9);
  }
}
}  // namespace

RC_GTEST_PROP(NormalEncodingProperty, WithinTheCellSupremumAt8Bits, ()) {
  const ne::vec3 n = *unit_normal();
  for (const auto& m : ne::methods()) check(m, 8, n);
}

RC_GTEST_PROP(NormalEncodingProperty, OctahedralWithinItsSupremumAt10Bits, ()) {
  const ne::vec3 n = *unit_normal();
  for (auto id : {ne::method_id::octahedral, ne::method_id::octahedral_precise, ne::method_id::octahedral_snorm})
    check(ne::method_of(id), 10, n);
}

RC_GTEST_PROP(NormalEncodingProperty, The2010EncodersIgnoreTheInputLength, (std::uint8_t scale)) {
  // Normalising first makes every method scale-invariant: n and (1 + scale/64)·n get one code.
  const ne::vec3 n = *unit_normal();
  const double s = 0.25 + scale / 64.0;
  for (const auto& m : ne::methods()) RC_ASSERT(ne::encode_2010(m, s * n, 8) == ne::encode_2010(m, n, 8));
}
