// What the certified relaxation step of two-pass.max-s.interpolated leaves at the next s
// (two_pass_triangle/relaxation_classes.hpp uncertified_next_s, which prove reports): the whole survey at
// certified_relaxation_s + 1, re-run here because it takes ~2.5 min per gouraud_fraction value. The
// classes that stay uncertified, and the normals in them, are the same under every tfx_rounding ×
// blend_shift value; the counts and the normals are prove's figures; the relaxation witness at that s
// (relaxation_witnesses, above the threshold by relaxation_value, another function) lies in one of
// the uncertified classes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "proofs/paper_code.hpp"
#include "two_pass_triangle/relaxation_classes.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"
#include "proofs/two_pass.hpp"

namespace tc = gsdot3::proofs::two_pass::triangle::certify;
namespace tt = gsdot3::proofs::two_pass::triangle;
namespace p = gsdot3::proofs;

namespace {
using class_key = std::tuple<int, int, int, std::int64_t>;
std::set<class_key> keys(const std::vector<tc::open_class>& classes) {
  std::set<class_key> out;
  for (const auto& c : classes) out.insert({c.w[0], c.w[1], c.w[2], c.threshold128});
  return out;
}
gs::model_options with(gs::gouraud_fraction g, gs::tfx_rounding t = gs::tfx_rounding::floor,
                       gs::blend_shift b = gs::blend_shift::floor) {
  gs::model_options o;
  o.gouraud = g, o.tfx = t, o.shift = b;
  o.setup = gs::gouraud_setup::plane_steps;
  return o;
}
std::vector<std::pair<int, int>> codes(const std::vector<p::paper::packed_normal>& normals) {
  std::vector<std::pair<int, int>> out;
  for (const auto& nm : normals) out.push_back({nm.iX, nm.iY});
  return out;
}
// The class of a relaxation witness: its normal's |n| sorted and its side's threshold.
class_key witness_key(const tt::relaxation_witness& w, const gs::model_options& o) {
  const auto nm = p::paper::pack_normal_from(w.iX, w.iY);
  std::array<int, 3> a{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
  std::sort(a.begin(), a.end());
  const p::two_pass::table t(o);
  return {a[0], a[1], a[2], tt::relaxation_threshold_units(nm, t.alpha_error(nm), w.side, o)};
}
}  // namespace

TEST(CertifyNextS, WhatStaysUncertifiedIsWhatProveReports) {
  for (const auto g : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
    const gs::model_options o = with(g);
    const tc::next_s_survey stored = tc::uncertified_next_s(o);
    ASSERT_EQ(stored.s, tc::certified_relaxation_s(o) + 1);
    const auto open = tc::uncertified_classes(stored.s, o);
    EXPECT_EQ(static_cast<int>(open.size()), stored.uncertified) << "s = " << stored.s;
    const auto normals = codes(tc::normals_in(open, stored.s, o));
    EXPECT_EQ(static_cast<std::int64_t>(normals.size()), stored.normals) << "s = " << stored.s;
    const auto all = tc::open_classes(stored.s, o);
    EXPECT_EQ(static_cast<int>(all.size()), stored.classes) << "s = " << stored.s;
    EXPECT_LT(open.size(), all.size()) << "the relaxation certifies none of the classes at s = " << stored.s;
    const auto open_keys = keys(open);
    int witnesses = 0;
    for (const auto& w : tt::relaxation_witnesses()) {
      if (w.s != stored.s || w.gouraud != g) continue;
      ++witnesses;
      EXPECT_EQ(open_keys.count(witness_key(w, o)), 1u)
          << "a class holding a relaxation point above its threshold closed";
    }
    EXPECT_EQ(witnesses, 1) << "s = " << stored.s;
    for (const auto t : {gs::tfx_rounding::floor, gs::tfx_rounding::truncate})
      for (const auto b : {gs::blend_shift::floor, gs::blend_shift::truncate}) {
        if (t == gs::tfx_rounding::floor && b == gs::blend_shift::floor) continue;
        const gs::model_options v = with(g, t, b);
        EXPECT_EQ(keys(tc::open_classes(stored.s, v)), keys(all)) << "the classes move with tfx_rounding / blend_shift";
        EXPECT_EQ(codes(tc::normals_in(open, stored.s, v)), normals)
            << "the normals move with tfx_rounding / blend_shift";
      }
  }
  gs::model_options per_pixel;
  per_pixel.setup = gs::gouraud_setup::per_pixel;
  EXPECT_EQ(tc::uncertified_next_s(per_pixel).s, 0);
}
