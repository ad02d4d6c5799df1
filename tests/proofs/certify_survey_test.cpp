// The certified relaxation step of two-pass.max-s.interpolated (two_pass_triangle/relaxation_classes.hpp), re-run
// in full: prove takes certified_relaxation_s (83 under keep_fraction, 82 under truncate_to_8) because
// the branch and bound over every open class takes ~23 s per gouraud_fraction value. Here the open
// classes at that s are the same under every value of the claim's other options (so certifying them
// once per gouraud_fraction covers every option combination), every one of them closes, and s + 1 does
// not close (the relaxation itself exceeds the wrap threshold there: relaxation_witnesses() has a
// point at 84 and at 83).
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "two_pass_triangle/relaxation_classes.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"

namespace tc = gsdot3::proofs::two_pass::triangle::certify;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
using class_key = std::tuple<int, int, int, std::int64_t>;
std::set<class_key> keys(int s, const gs::model_options& o) {
  std::set<class_key> out;
  for (const auto& c : tc::open_classes(s, o)) out.insert({c.w[0], c.w[1], c.w[2], c.threshold128});
  return out;
}
gs::model_options with(gs::gouraud_fraction g, gs::tfx_rounding t = gs::tfx_rounding::floor,
                       gs::blend_shift b = gs::blend_shift::floor) {
  gs::model_options o;
  o.gouraud = g, o.tfx = t, o.shift = b;
  o.setup = gs::gouraud_setup::plane_steps;
  return o;
}
constexpr gs::gouraud_fraction fractions[] = {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8};
}  // namespace

TEST(CertifySurvey, EveryOpenClassClosesAtTheCertifiedSUnderEveryOptionCombination) {
  for (const auto g : fractions) {
    const gs::model_options o = with(g);
    const int s = tc::certified_relaxation_s(o);
    ASSERT_GT(s, 0);
    const auto classes = keys(s, o);
    EXPECT_FALSE(classes.empty()) << "the bound alone settles s = " << s << ": nothing to certify";
    for (const auto t : {gs::tfx_rounding::floor, gs::tfx_rounding::truncate})
      for (const auto b : {gs::blend_shift::floor, gs::blend_shift::truncate}) {
        EXPECT_EQ(tc::certified_relaxation_s(with(g, t, b)), s);
        EXPECT_EQ(keys(s, with(g, t, b)), classes) << "the classes move with tfx_rounding / blend_shift";
      }
    EXPECT_TRUE(tc::relaxation_certified(s, o)) << "s = " << s;
  }
}

TEST(CertifySurvey, TheNextSDoesNotClose) {
  for (const auto g : fractions) {
    const gs::model_options o = with(g);
    const int s = tc::certified_relaxation_s(o) + 1;
    EXPECT_FALSE(tc::relaxation_certified(s, o)) << "s = " << s;
    bool witness = false;  // and the ledger holds a relaxation point above the threshold at that s
    for (const auto& w : tt::relaxation_witnesses()) witness = witness || (w.s == s && w.gouraud == g);
    EXPECT_TRUE(witness) << "s = " << s;
  }
}
