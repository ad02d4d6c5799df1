// Seed 001 (C. Green, "Efficient Self-Shadowed Radiosity Normal Mapping", 2007): the basis, eq. (3)'s
// zero sum, the tools' flat outputs, precision of the 8-bit RNM and SSBump paths, filtering, and the
// normal rebuilt from SSBump weights. The scheme's own choices (shader precision fp32 / fp24, the
// tool's truncating or rounding writer, shipped or exact float basis) are evaluated inside each
// claim and named in the figure names.
#include <cmath>
#include <cstdio>
#include <string>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/valve_sweeps.hpp"
#include "valve/basis.hpp"
#include "valve/encode.hpp"
#include "valve/height2ssbump.hpp"
#include "valve/q23.hpp"

namespace gsdot3::proofs::claims {

namespace v = gsdot3::valve;
namespace vs = valve_sweeps;

namespace {

std::string rgb_hex(std::uint32_t rgb) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%06x", rgb);
  return buf;
}

// "B0·B1" (snprintf: GCC 12's -Wrestrict misfires on chains of std::string + literal).
std::string pair_name(std::size_t i, std::size_t j) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "B%zu·B%zu", i, j);
  return buf;
}

std::string q23_text(const v::q23& q) {
  // Only rationals occur in the Gram matrices; anything else is printed by value.
  if (q.n[1] == 0 && q.n[2] == 0 && q.n[3] == 0)
    return q.den == 1 ? std::to_string(q.n[0]) : std::to_string(q.n[0]) + "/" + std::to_string(q.den);
  return std::to_string(q.value());
}

// The figures of one error distribution, named prefix_{max,mean,rmse}.
void add_stat(outcome& o, const std::string& prefix, const vs::stat& s) {
  o.figures.push_back(fig_real(prefix + "_max", s.max));
  o.figures.push_back(fig_real(prefix + "_mean", s.mean()));
  o.figures.push_back(fig_real(prefix + "_rmse", s.rmse()));
}

const vs::precision_result& catalogue_precision(const sweep_config& cfg) {
  static const vs::precision_result r = vs::precision_sweep(vs::texel_domain::catalogue(), cfg);
  return r;
}

// The float's distance in ulps from the float nearest to x.
std::int64_t ulps_from_nearest(float f, double x) {
  const float n = static_cast<float>(x);
  return static_cast<std::int64_t>(std::bit_cast<std::int32_t>(f)) - std::bit_cast<std::int32_t>(n);
}

}  // namespace

outcome valve_eq1_not_orthonormal(const gs::model_options&, const sweep_config&) {
  // Exact Gram matrix of eq. (1) as printed, in Q(√2, √3).
  const auto& B = v::printed_basis_q23;
  outcome o;
  o.domain_size = 6;
  tally t;
  std::uint64_t index = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i; j < 3; ++j, ++index) {
      const v::q23 g = v::dot(B[i], B[j]);
      o.figures.push_back(fig_real(pair_name(i, j), g.value()));
      if (!(g == v::q23::rational(i == j ? 1 : 0))) {
        t.add(index);
        std::string w = pair_name(i, j);
        w += " = ";
        w += q23_text(g);
        w += i == j ? " (want 1)" : " (want 0)";
        o.witnesses.push_back(w);
      }
    }
  o.result = t.count ? verdict::refuted : verdict::proven;
  o.counterexamples = t.count;
  o.note =
      "as printed, B0 = B1 and B0·B2 = B1·B2 = 2/3 exactly: eq. (1) is misprinted (Source's bumpvects.h basis is "
      "orthonormal)";
  return o;
}

outcome valve_source_basis_orthonormal(const gs::model_options&, const sweep_config&) {
  // Exact Gram matrix = I in Q(√2, √3); then Σ(N·B_i)² = |N|² (Parseval) for every N. Dense check:
  // unit N on a 721 × 1441 (θ, φ) grid in double.
  const auto& B = v::exact_basis_q23;
  tally t;
  std::uint64_t index = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i; j < 3; ++j, ++index)
      if (!(v::dot(B[i], B[j]) == v::q23::rational(i == j ? 1 : 0))) t.add(index);
  double worst = 0;
  for (int a = 0; a <= 720; ++a)
    for (int b = 0; b <= 1440; ++b) {
      const double th = a * std::numbers::pi / 720, ph = b * std::numbers::pi / 720;
      const v::vec3<double> n{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      double s = 0;
      for (const auto& e : v::exact_basis) s += v::dot(n, e) * v::dot(n, e);
      worst = std::max(worst, std::fabs(s - 1.0));
    }
  outcome o = verdict_of(t, 6, [](std::uint64_t i) { return "Gram entry " + std::to_string(i); });
  o.figures = {fig_real("sampled_max_abs_sum_sq_minus_1_double", worst), fig("sample_points", 721 * 1441)};
  o.note =
      "B_i·B_j = δ_ij exactly (Q(√2, √3)), so Σ(N·B_i)² = |N|² = 1 for unit N; the sampled deviation is double "
      "rounding";
  return o;
}

outcome valve_float_literals(const gs::model_options&, const sweep_config& cfg) {
  // The shipped float literals against the floats nearest to the exact values; the Gram matrix of
  // the shipped basis (double arithmetic on the floats); M = Σ B_i B_iᵀ − I bounds
  // |Σ(N·B_i)² − 1| ≤ ‖M‖_F for unit N; the effect on normal2ssbump's 8-bit output (catalogue domain).
  const auto& F = v::source_basis_float;
  outcome o;
  o.result = verdict::bound;
  o.figures = {fig("B0.x_ulps", ulps_from_nearest(F[0].x, v::sqrt_2_3)),
               fig("B1.x_ulps", ulps_from_nearest(-F[1].x, v::inv_sqrt6)),
               fig("B2.x_ulps", ulps_from_nearest(-F[2].x, v::inv_sqrt6)),
               fig("B1.y_ulps", ulps_from_nearest(F[1].y, v::inv_sqrt2)),
               fig("B2.y_ulps", ulps_from_nearest(-F[2].y, v::inv_sqrt2)),
               fig("z_ulps", ulps_from_nearest(F[0].z, v::inv_sqrt3))};
  const v::basis3 S = v::source_basis;
  double gram = 0, frob = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      gram = std::max(gram, std::fabs(v::dot(S[i], S[j]) - (i == j ? 1.0 : 0.0)));
      const auto c = [&](const v::vec3<double>& b, std::size_t k) { return k == 0 ? b.x : k == 1 ? b.y : b.z; };
      double m = 0;
      for (const auto& b : S) m += c(b, i) * c(b, j);
      frob += (m - (i == j ? 1.0 : 0.0)) * (m - (i == j ? 1.0 : 0.0));
    }
  const auto& p = catalogue_precision(cfg);
  o.domain_size = p.domain;
  o.figures.push_back(fig_real("gram_max_abs_deviation", gram));
  o.figures.push_back(fig_real("bound_abs_sum_sq_minus_1", std::sqrt(frob)));
  o.figures.push_back(
      fig("normal2ssbump_texels_changed_vs_exact_float_basis", static_cast<std::int64_t>(p.literal_changes)));
  o.note =
      "the literals are within a few ulps of the exact values: Σ(N·B_i)² stays within the bound of 1, and the 8-bit "
      "normal2ssbump output differs on the counted texels from the one with the exactly rounded basis";
  return o;
}

outcome valve_zero_sum(const gs::model_options&, const sweep_config& cfg) {
  const auto r = vs::zero_sum_sweep(cfg);
  outcome o;
  o.result = r.exact ? verdict::refuted : verdict::proven;
  o.domain_size = r.domain;
  o.counterexamples = r.exact;
  for (auto w : r.first) o.witnesses.push_back("texel " + rgb_hex(w) + " => Σd = 0, shader 0/0 = NaN");
  o.figures = {fig("zero_sum_exact", static_cast<std::int64_t>(r.exact)),
               fig("zero_sum_fp32", static_cast<std::int64_t>(r.fp32)),
               fig("zero_sum_fp24_rne", static_cast<std::int64_t>(r.fp24)),
               fig("zero_sum_not_nan_fp32", static_cast<std::int64_t>(r.not_nan_fp32)),
               fig("zero_sum_not_nan_fp24_rne", static_cast<std::int64_t>(r.not_nan_fp24)),
               fig("zero_sum_normal2ssbump_not_nan", static_cast<std::int64_t>(r.tool_not_nan))};
  o.note =
      "every N·B_i ≤ 0 (a cone around −z) for these texels: Listing 1 divides 0 by 0 (NaN, in fp32 and fp24) and "
      "normal2ssbump writes NaN weights";
  return o;
}

outcome valve_flat_normal(const gs::model_options&, const sweep_config&) {
  // Exact: (B_i·ẑ)² = (1/√3)² = 1/3 for each i (Q(√2, √3)); then the 8-bit texels nearest the flat
  // normal through Source's normal2ssbump; then an 8×8 flat height field through height2ssbump.
  tally t;
  for (std::size_t i = 0; i < 3; ++i) {
    const v::q23 d = v::exact_basis_q23[i].z * v::exact_basis_q23[i].z;
    if (!(d == v::q23::rational(1, 3))) t.add(i);
  }
  outcome o = verdict_of(t, 3 + 4 + 64, [](std::uint64_t i) { return pair_name(i, i) + " over z: (B·z)² ≠ 1/3"; });
  for (int r : {127, 128})
    for (int g : {127, 128}) {
      const v::texel s =
          v::ssbump_texel(v::normal2ssbump({static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), 255}));
      o.figures.push_back(
          fig("normal2ssbump_" + rgb_hex((std::uint32_t(r) << 16) | (std::uint32_t(g) << 8) | 255) + "_sum",
              s.r + s.g + s.b));
      o.witnesses.push_back("normal2ssbump " + rgb_hex((std::uint32_t(r) << 16) | (std::uint32_t(g) << 8) | 255) +
                            " => " + rgb_hex(s.index()));
    }
  v::height2ssbump_options h;
  h.bump_scale = 4.0f;
  h.threads = 1;
  const auto out = v::height2ssbump(std::vector<float>(64, 0.5f), 8, 8, h);
  std::int64_t flat147 = 0;
  for (const auto& w : out) flat147 += v::ssbump_texel(w) == v::texel{147, 147, 147} && w.x == 0.57735025882720947f;
  o.figures.push_back(fig("normal2ssbump_exact_flat_weight_thirds", 1));
  o.figures.push_back(fig_real("height2ssbump_flat_weight", out[0].x));
  o.figures.push_back(fig("height2ssbump_flat_texels_147", flat147));
  if (flat147 != 64) {
    o.result = verdict::refuted;
    o.counterexamples += static_cast<std::uint64_t>(64 - flat147);
  }
  o.note =
      "an exactly flat normal gives D = (1/3, 1/3, 1/3) (85 each in 8 bits) but no RGB8 texel is exactly flat: "
      "the four nearest give the sums shown; height2ssbump's flat unoccluded texel is 1/√3 = 0.57735 → 147";
  return o;
}

outcome valve_precision(const gs::model_options&, const sweep_config& cfg) {
  const auto& r = catalogue_precision(cfg);
  outcome o;
  o.result = verdict::bound;
  o.domain_size = r.domain;
  static const char* path[4] = {"rnm_fp32", "rnm_fp24_rne", "ssbump_normal2ssbump_trunc",
                                "ssbump_normal2ssbump_nearest"};
  for (int p = 0; p < 4; ++p) {
    add_stat(o, std::string(path[p]) + "_all", r.err[p][0]);
    add_stat(o, std::string(path[p]) + "_unit", r.err[p][1]);
    o.witnesses.push_back(std::string(path[p]) + " max at texel " +
                          rgb_hex(static_cast<std::uint32_t>(vs::texel_domain::catalogue().rgb(r.err[p][0].arg_max))));
  }
  for (int p = 0; p < 4; ++p)
    o.figures.push_back(fig(std::string(path[p]) + "_nan_texels", static_cast<std::int64_t>(r.nan[p])));
  const auto t = vs::true_normal_sweep(0.25);
  add_stat(o, "from_unit_normal_rnm_fp32", t.rnm_fp32);
  add_stat(o, "from_unit_normal_ssbump_ideal_nearest", t.ssbump_ideal);
  add_stat(o, "from_unit_normal_ssbump_normal2ssbump_trunc", t.ssbump_source);
  o.figures.push_back(fig("from_unit_normal_samples", static_cast<std::int64_t>(t.samples)));
  o.figures.push_back(fig("zero_sum_texels_skipped", static_cast<std::int64_t>(r.zero_sum)));
  o.figures.push_back(fig("unit_texels", static_cast<std::int64_t>(r.unit_texels)));
  o.note =
      "errors in 1/255 of a unit lightmap against eq. (3) on the exactly normalised normal of the texel (lights: the "
      "three unit lightmap colours); 'unit' = texels with | |N| − 1 | ≤ √3/255; NaN results are counted, not measured. "
      "from_unit_normal: a 0.25° grid of unit normals stored either way, against eq. (3) on the normal itself";
  return o;
}

outcome valve_ssbump_filter_linear(const gs::model_options&, const sweep_config&) {
  // Listing 2 is linear in the texel: Σ_i (Σ_k w_k t_k,i)·L_i = Σ_k w_k (Σ_i t_k,i·L_i) by
  // distributivity, for every filter that takes an affine combination of texels (bilinear, box mip).
  // Checked exactly in integers for every channel pair (a, b), every 4-bit weight w (w/16) and every
  // 8-bit lightmap value L: 16·255·lighting of the filtered texel = blend of the 16·255·lightings.
  // The fp32 figure: the shader's value of the filtered texel against the blend of its two values.
  tally t;
  double fp32_dev = 0;
  std::uint64_t index = 0;
  for (int a = 0; a < 256; ++a)
    for (int b = 0; b < 256; ++b)
      for (int w = 0; w <= 16; ++w, ++index) {
        const std::int64_t f = (16 - w) * a + w * b;  // 16·filtered texel
        for (int L = 0; L < 256; L += 51)
          if (f * L != (16 - w) * (a * L) + w * (b * L)) t.add(index);
        const double filtered = static_cast<double>(static_cast<float>(f / (16.0 * 255.0)));
        const double blended = ((16 - w) * static_cast<double>(static_cast<float>(a / 255.0)) +
                                w * static_cast<double>(static_cast<float>(b / 255.0))) /
                               16.0;
        fp32_dev = std::max(fp32_dev, std::fabs(filtered - blended) * 255.0);
      }
  outcome o = verdict_of(t, index, [](std::uint64_t i) { return "pair/weight " + std::to_string(i); });
  o.figures = {fig_real("fp32_max_deviation_255ths", fp32_dev)};
  o.note =
      "SSBump lighting of a filtered texel is exactly the filtered lighting (linear); in fp32 only the texel "
      "conversion's rounding differs";
  return o;
}

outcome valve_rnm_filter(const gs::model_options&, const sweep_config& cfg) {
  const auto r = vs::rnm_filtering_sweep(16, cfg);
  outcome o;
  o.result = verdict::bound;
  o.domain_size = r.all.n;
  add_stat(o, "err_all", r.all);
  add_stat(o, "err_within_10deg", r.near);
  for (int w = 1; w <= 15; ++w)
    o.figures.push_back(fig_real("err_max_w" + std::to_string(w) + "_16", r.by_weight[w - 1].max));
  o.figures.push_back(fig("texels", static_cast<std::int64_t>(r.texels)));
  o.figures.push_back(fig("pairs", static_cast<std::int64_t>(r.pairs)));
  o.figures.push_back(fig("over_half_255th", static_cast<std::int64_t>(r.over_half)));
  o.figures.push_back(fig("over_one_255th", static_cast<std::int64_t>(r.over_one)));
  o.witnesses.push_back("worst: texels " + rgb_hex(r.worst_a) + ", " + rgb_hex(r.worst_b) +
                        " at w = " + std::to_string(r.worst_w) + "/16");
  o.note =
      "RNM's weights of the filtered normal differ from the filtered weights (eq. (3) is not linear), by up to the "
      "max shown in 1/255 units (three unit lights), exact arithmetic";
  return o;
}

outcome valve_reconstruct_normal(const gs::model_options&, const sweep_config& cfg) {
  const auto& r = catalogue_precision(cfg);
  outcome o;
  o.result = verdict::bound;
  o.domain_size = r.reconstruct[0][0].n;
  add_stat(o, "deg_sum_DB_all", r.reconstruct[0][0]);
  add_stat(o, "deg_sum_DB_cone", r.reconstruct[0][1]);
  add_stat(o, "deg_sum_sqrtDB_all", r.reconstruct[1][0]);
  add_stat(o, "deg_sum_sqrtDB_cone", r.reconstruct[1][1]);
  o.witnesses.push_back("Σ D·B worst at texel " +
                        rgb_hex(vs::texel_domain::catalogue().rgb(r.reconstruct[0][0].arg_max)));
  o.note =
      "normalize(Σ D_i·B_i) of the 8-bit SSBump texel (normal2ssbump) against the texel's normal, in degrees; "
      "'cone' = every N·B_i ≥ 0, where normalize(Σ √D_i·B_i) inverts eq. (3) up to quantisation";
  return o;
}

}  // namespace gsdot3::proofs::claims
