// Appendices 1 and 2 (the paper's encoders) and section 3.5's n_a rounding.
#include <cmath>
#include <string>

#include "gs_arith/bilinear.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/methods.hpp"
#include "proofs/claims.hpp"
#include "proofs/domains.hpp"
#include "proofs/paper_code.hpp"

namespace gsdot3::proofs::claims {

namespace {
std::string describe_normal(const paper::packed_normal& p) {
  return "(iX, iY, iZ) = (" + std::to_string(p.iX) + ", " + std::to_string(p.iY) + ", " + std::to_string(p.iZ) + ")";
}
}  // namespace

outcome appendix2_packing(const gs::model_options&, const sweep_config&) {
  const auto& normals = appendix2_normals();
  tally bad;
  extremes alpha, iz;
  std::int64_t clamp_changes = 0, typo_branch = 0, b_neg = 0;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const auto& p = normals[i];
    alpha.add(p.alpha_unclamped, i);
    iz.add(p.iZ, i);
    if (p.alpha != p.alpha_unclamped) ++clamp_changes;
    if (p.iX > 255) ++typo_branch;
    if (p.B_neg != 0) ++b_neg;
    if (!p.assert_le || !p.assert_gt || p.B_neg != 0) bad.add(i);
  }
  auto out = verdict_of(bad, normals.size(), [&](auto i) { return describe_normal(normals[i]); });
  out.figures = {fig("normals", static_cast<std::int64_t>(normals.size())),
                 fig("alpha_min", alpha.min),
                 fig("alpha_max", alpha.max),
                 fig("iz_min", iz.min),
                 fig("iz_max", iz.max),
                 fig("b_neg_nonzero", b_neg),
                 fig("alpha_clamp_changes", clamp_changes),
                 fig("iX_gt_255_branch", typo_branch)};
  out.note = "both asserts hold and B_neg = 0 for every reachable (iX, iY); alpha stays in " +
             std::to_string(alpha.min) + ".." + std::to_string(alpha.max) +
             ", so the clamp never bites — its `iX > 255` test (meant: alpha > 255) "
             "can never fire either, iX <= 128";
  return out;
}

outcome two_pass_na_rounding(const gs::model_options& o, const sweep_config&) {
  // n_a = Σ (128 + Max(−n, 0) − Max(n, 0)) = 384 + delta; n'_a = (n_a + 1) / 3 (the alpha of Appendix 2).
  const auto& normals = appendix2_normals();
  extremes na, prime, err;
  std::int64_t over_255 = 0;
  std::vector<bool> seen(1024);
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const auto& p = normals[i];
    const int n_a = 3 * 128 + p.delta, n_prime = (n_a + 1) / 3;
    na.add(n_a, i), prime.add(n_prime, i), err.add(3 * n_prime - n_a, i);
    if (n_a > 255) ++over_255;
    seen[static_cast<std::size_t>(n_a)] = true;
  }
  // The paper's reason for n'_a: "the bilinearly interpolated values will be wrong". Every pair of
  // neighbouring texels' n_a values × every weight the model's footprint gives (gs::footprint over
  // one texel of u; 16 weights for lerp16_4, only 0 for nearest), filtered by gs::lerp16_4:
  // (1) n_a stored mod 256: wrong when the filtered byte is not the filtered n_a mod 256;
  // (2) n'_a stored: 3·filtered n'_a against the filtered n_a (value level: x0 + floor((x1 − x0)·w/16)).
  std::vector<int> values;
  for (int v = 0; v < 1024; ++v)
    if (seen[static_cast<std::size_t>(v)]) values.push_back(v);
  std::vector<int> weights;
  for (int u16 = 8; u16 < 24; ++u16) weights.push_back(gs::footprint(u16, 8, o.bilinear).wu.value());
  auto ideal = [](int x0, int x1, int w) { return x0 + fixed::shift_right<fixed::rounding::floor>((x1 - x0) * w, 4); };
  std::int64_t unscaled_wrong = 0;
  extremes scaled_err;
  std::uint64_t filter_index = 0;
  for (int x0 : values)
    for (int x1 : values)
      for (int w : weights) {
        const auto W = fixed::u4::from_wrapped(w);
        const int want = ideal(x0, x1, w);
        const int raw = gs::lerp16_4(methods::byte(x0), methods::byte(x1), W).value();
        if (raw != (want & 0xFF)) ++unscaled_wrong;
        const int scaled = gs::lerp16_4(methods::byte((x0 + 1) / 3), methods::byte((x1 + 1) / 3), W).value();
        scaled_err.add(3 * scaled - want, filter_index++);
      }
  outcome out;
  out.result = verdict::bound;
  out.domain_size = normals.size() + filter_index;
  out.figures = {fig("na_min", na.min),
                 fig("na_max", na.max),
                 fig("na_prime_min", prime.min),
                 fig("na_prime_max", prime.max),
                 fig("error_min", err.min),
                 fig("error_max", err.max),
                 fig("na_over_255", over_255),
                 fig("filter_cases", static_cast<std::int64_t>(filter_index)),
                 fig("unscaled_filter_wrong", unscaled_wrong),
                 fig("scaled_filter_err_min", scaled_err.min),
                 fig("scaled_filter_err_max", scaled_err.max)};
  out.witnesses = {
      "na_max at " + describe_normal(normals[na.arg_max]), "na_min at " + describe_normal(normals[na.arg_min]),
      "error_min at " + describe_normal(normals[err.arg_min]), "error_max at " + describe_normal(normals[err.arg_max])};
  out.note = "n_a exceeds 255 for " + std::to_string(over_255) +
             " normals, as the paper says, and filtering n_a mod 256 "
             "goes wrong in " +
             std::to_string(unscaled_wrong) +
             " of the filter cases; n'_a fits a byte, 3·n'_a − n_a is "
             "the rounding the two-pass method accepts, and filtered n'_a stays within the scaled_filter_err range";
  return out;
}

namespace {
// The exact unit direction a sphere-map texel stands for (Appendix 1's derivation, in double):
// with s2 = 2s − 1, t2 = 2t − 1, ρ² = s2² + t2²: L = (2·s2·√(1−ρ²), 2·t2·√(1−ρ²), 1 − 2ρ²).
std::array<double, 3> exact_direction(int x, int y, int size) {
  const double s2 = 2.0 * (x + 0.5) / size - 1.0, t2 = 2.0 * (y + 0.5) / size - 1.0;
  const double rho2 = s2 * s2 + t2 * t2, w = std::sqrt(std::max(0.0, 1.0 - rho2));
  return {2.0 * s2 * w, 2.0 * t2 * w, 1.0 - 2.0 * rho2};
}
double angle_degrees(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  const double cross = std::sqrt(cx * cx + cy * cy + cz * cz), dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  return std::atan2(cross, dot) * 180.0 / 3.14159265358979323846;
}
}  // namespace

outcome appendix1_sphere_map(const gs::model_options&, const sweep_config&) {
  tally bad;
  std::uint64_t index = 0;
  double worst = 0;
  std::string worst_at;
  std::vector<figure> figures;
  for (int size : {16, 32, 64, 128, 256}) {
    double worst_size = 0;
    std::int64_t inside = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x, ++index) {
        const auto t = paper::sphere_map_texel(x, y, size, size);
        auto in_byte = [](int v) { return v >= 0 && v < 256; };
        if (!in_byte(t.r) || !in_byte(t.g) || !in_byte(t.b)) bad.add(index);
        if (!t.inside) continue;
        ++inside;
        const std::array<double, 3> packed{128.0 - t.r, 128.0 - t.g, 128.0 - t.b};
        const double a = angle_degrees(packed, exact_direction(x, y, size));
        if (a > worst_size) worst_size = a;
        if (a > worst) {
          worst = a;
          worst_at = std::to_string(size) + "x" + std::to_string(size) + " texel (" + std::to_string(x) + ", " +
                     std::to_string(y) + ") packed (" + std::to_string(t.r) + ", " + std::to_string(t.g) + ", " +
                     std::to_string(t.b) + ")";
        }
      }
    figures.push_back(fig("inside_" + std::to_string(size), inside));
    figures.push_back(fig_real("worst_angle_deg_" + std::to_string(size), worst_size));
  }
  auto out = verdict_of(bad, index, [](auto i) { return "texel index " + std::to_string(i); });
  figures.push_back(fig_real("worst_angle_deg", worst));
  out.figures = std::move(figures);
  out.witnesses.push_back("worst angle at " + worst_at);
  out.note =
      "every texel's r, g, b is in 0..255 at every size; the worst angle is between 128 − (r, g, b) and the "
      "texel centre's exact direction";
  return out;
}

}  // namespace gsdot3::proofs::claims
