// Section 3.1 steps 2.6 and 4: the light accumulation buffer (LAB) — the ILP look-up times the light
// colour added into it, its saturation with many lights, and the diffuse layer times it. Each GS
// value runs through the model's units with the register sets the renderer draws with
// (gs_methods' ilp_into_lab, multiply_red); each expected value is the exact integer formula.
#include <algorithm>
#include <string>
#include <vector>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/methods.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;

namespace {

// Step 2.6 on one channel: the ILP texel (intensity i in R, G, B) MODULATE the flat light colour c,
// added to the LAB byte d by the blend Cs + Cd with COLCLAMP = 1.
int ilp_into_lab(int i, int c, int d, const gs::model_options& o) {
  constexpr const gs_methods::pass_regs& p = gs_methods::ilp_into_lab;
  const gs::rgba8 cs =
      gs::texture_function(p.TFX, p.TCC, m::grey(i, 0x80), gs::fragment_colour::flat(m::grey(c, 0x80)), o);
  return gs::colclamp(gs::alpha_blend(p.ALPHA, cs, m::grey(d, 0), o), cs.a, p.CLAMP).r.value();
}

// Step 4 on one channel: the diffuse texel t (DECAL) times the LAB byte l moved into the destination
// alpha, (Cs − 0)·Ad >> 7 with COLCLAMP = 1.
int diffuse_times_lab(int t, int l, const gs::model_options& o) {
  constexpr const gs_methods::pass_regs& p = gs_methods::multiply_red;
  const gs::rgba8 cs =
      gs::texture_function(p.TFX, p.TCC, m::grey(t, 0x80), gs::fragment_colour::flat(m::grey(0x80, 0x80)), o);
  return gs::colclamp(gs::alpha_blend(p.ALPHA, cs, m::grey(0, l), o), cs.a, p.CLAMP).r.value();
}

struct product_acc {
  tally bad;
  std::uint64_t saturated = 0, unit_wrong = 0;
  extremes loss;  // (exact product − GS contribution) in 1/128 units, where unsaturated
  void merge(const product_acc& l) {
    bad.merge(l.bad);
    saturated += l.saturated;
    unit_wrong += l.unit_wrong;
    loss.merge(l.loss);
  }
};

// The figures of a product sweep: what floor drops at most, how many cases clamp, how many unit
// cases (the factor that stands for 1.0) do not give the other factor back.
std::vector<figure> product_figures(const product_acc& r, const char* unit_case) {
  return {fig("loss_max_128ths", r.loss.max), fig("saturated", static_cast<std::int64_t>(r.saturated)),
          fig(unit_case, static_cast<std::int64_t>(r.unit_wrong))};
}

}  // namespace

outcome ilp_light_into_lab(const gs::model_options& o, const sweep_config& cfg) {
  // Index: i = k / 65536 (0..128), c = (k >> 8) & 0xFF, d = k & 0xFF.
  constexpr std::uint64_t n = 129ull * 256 * 256;
  auto r = sweep<product_acc>(n, cfg, [&](product_acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto k = lo; k < hi; ++k) {
      const int i = static_cast<int>(k >> 16), c = static_cast<int>((k >> 8) & 0xFF), d = static_cast<int>(k & 0xFF);
      const int gs = ilp_into_lab(i, c, d, o), exact = d + i * c / 128;  // the expected value: floor, clamped
      if (gs != std::min(255, exact)) s.bad.add(k);
      if (exact > 255)
        ++s.saturated;
      else
        s.loss.add(128 * d + i * c - 128 * exact, k);  // what floor drops, in 1/128
      if (i == 128 && d == 0 && gs != c) ++s.unit_wrong;
    }
  });
  auto out = verdict_of(r.bad, n, [&](std::uint64_t k) {
    const int i = static_cast<int>(k >> 16), c = static_cast<int>((k >> 8) & 0xFF), d = static_cast<int>(k & 0xFF);
    return "ILP " + hexdec(i) + ", light " + hexdec(c) + ", LAB " + hexdec(d) + " => GS " +
           hexdec(ilp_into_lab(i, c, d, o)) +
           ", min(255, LAB + floor(ILP·light/128)) = " + hexdec(std::min(255, d + i * c / 128));
  });
  out.figures = product_figures(r, "full_intensity_not_light");
  out.note =
      "one light adds floor(ILP·colour/128) to each LAB channel, clamped at 255: the look-up times the colour "
      "with 0x80 = 1.0 (ILP 128, a dot product of 127, adds the colour itself), rounded down by less than 1";
  return out;
}

outcome lab_saturation(const gs::model_options& o, const sweep_config& cfg) {
  // Two lights' contributions x, y (any bytes MODULATE yields) added in turn to the LAB byte d with
  // COLCLAMP = 1 give min(255, d + x + y). Argument for n lights: clamping is monotone and x, y >= 0,
  // so min(255, min(255, d + x) + y) = min(255, d + x + y) is the step of an induction on the count;
  // the sweep checks that step through the model, which is what rests on the GS's blend and clamp.
  constexpr std::uint64_t n = 256ull * 256 * 256;
  auto add = [&](int d, int x) {
    const auto w = gs::alpha_blend(m::add_blend, m::grey(x, 0), m::grey(d, 0), o);
    return gs::colclamp(w, m::byte(0), true).r.value();
  };
  auto bad = sweep<tally>(n, cfg, [&](tally& t, std::uint64_t lo, std::uint64_t hi) {
    for (auto k = lo; k < hi; ++k) {
      const int d = static_cast<int>(k >> 16), x = static_cast<int>((k >> 8) & 0xFF), y = static_cast<int>(k & 0xFF);
      if (add(add(d, x), y) != std::min(255, d + x + y)) t.add(k);
    }
  });
  auto out = verdict_of(bad, n, [&](std::uint64_t k) {
    const int d = static_cast<int>(k >> 16), x = static_cast<int>((k >> 8) & 0xFF), y = static_cast<int>(k & 0xFF);
    return "LAB " + hexdec(d) + " + " + hexdec(x) + " + " + hexdec(y) + " => GS " + hexdec(add(add(d, x), y)) +
           ", min(255, sum) = " + hexdec(std::min(255, d + x + y));
  });
  // The paper's scene (§4): ambient 0x10 and lights at full intensity; how many lights of a colour
  // channel c saturate it: the least n with 0x10 + n·c > 255 (c = 0x98, the default green's G).
  out.figures = {fig("default_green_lights_to_saturate", (255 - 0x10) / 0x98 + 1)};
  out.note =
      "the LAB saturates exactly when ambient plus the lights' contributions pass 255, in any order: a channel "
      "past 255 stays at 255 (COLCLAMP on), so bright lights lose their excess, never wrap";
  return out;
}

outcome step4_diffuse_times_lab(const gs::model_options& o, const sweep_config& cfg) {
  constexpr std::uint64_t n = 65536;
  auto r = sweep<product_acc>(n, cfg, [&](product_acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto k = lo; k < hi; ++k) {
      const int t = static_cast<int>(k >> 8), l = static_cast<int>(k & 0xFF);
      const int gs = diffuse_times_lab(t, l, o), exact = t * l / 128;
      if (gs != std::min(255, exact)) s.bad.add(k);
      if (exact > 255)
        ++s.saturated;
      else
        s.loss.add(t * l - 128 * exact, k);  // what floor drops, in 1/128
      if (l == 0x80 && gs != t) ++s.unit_wrong;
    }
  });
  auto out = verdict_of(r.bad, n, [&](std::uint64_t k) {
    const int t = static_cast<int>(k >> 8), l = static_cast<int>(k & 0xFF);
    return "diffuse " + hexdec(t) + ", LAB " + hexdec(l) + " => GS " + hexdec(diffuse_times_lab(t, l, o)) +
           ", min(255, floor(diffuse·LAB/128)) = " + hexdec(std::min(255, t * l / 128));
  });
  out.figures = product_figures(r, "lab_0x80_not_identity");
  out.note =
      "step 4 gives min(255, floor(diffuse·LAB/128)) per channel: the product with LAB 0x80 = 1.0 (the diffuse "
      "texel itself), rounded down, and a LAB above 0x80 brightens up to the clamp";
  return out;
}

}  // namespace gsdot3::proofs::claims
