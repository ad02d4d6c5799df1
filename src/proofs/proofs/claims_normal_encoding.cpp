// Seed 002 (Pranckevičius 2009, "Compact Normal Storage for small G-Buffers"), its 2010 revision and
// octahedral encoding: every 2×8 code, the worst case over the whole sphere from the rounding cells
// (src/schemes/normal_encoding/cells.hpp), means over an area-uniform set, the 2009/2010 encoders,
// the sphere map = CryEngine 3 = Lambert equivalence, singularities and the ranking.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>

#include "normal_encoding/cells.hpp"
#include "normal_encoding/cryengine3.hpp"
#include "normal_encoding/methods.hpp"
#include "normal_encoding/sampling.hpp"
#include "normal_encoding/spheremap.hpp"
#include "normal_encoding/xy.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"

namespace gsdot3::proofs::claims {

namespace ne = normal_encoding;

namespace {
constexpr double deg = 180 / std::numbers::pi;
constexpr int bits8 = 8;
// The area-uniform set of the catalogue (sampling.hpp): 2^16 Fibonacci points.
constexpr std::uint64_t uniform_points = 65536;

std::string hexf(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}
std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}
std::string vec_text(ne::vec3 n) {
  return "(" + num(n.x) + ", " + num(n.y) + ", " + num(n.z) + ") = (" + hexf(n.x) + ", " + hexf(n.y) + ", " +
         hexf(n.z) + ")";
}
std::string code_text(const ne::method& m, ne::code q) {
  std::string s = "(" + std::to_string(q.c[0]) + ", " + std::to_string(q.c[1]);
  if (m.channels == 3 || m.id == ne::method_id::xy_sign) s += ", " + std::to_string(q.c[2]);
  return s + ")";
}
std::string name(const ne::method& m) { return std::string(m.name); }
// The methods with a rounding-cell analysis of their own (octahedral-precise is bounded by octahedral's).
bool cell_method(const ne::method& m) { return m.id != ne::method_id::octahedral_precise; }
}  // namespace

outcome normal_encoding_codes(const gs::model_options&, const sweep_config&) {
  // Every 2×8 code of every two-channel method (#2: × its sign bit; #3a: its 256 × 256 codes):
  // decoded, classified as unit (| |d| − 1 | <= 1e-9), finite but not unit, or NaN/Inf; the
  // number of distinct decoded directions (components of the normalised vector rounded to 1e-9:
  // codes the mapping identifies, e.g. octahedral's folded border, differ in the last ulps).
  outcome o;
  o.result = verdict::bound;
  std::uint64_t total = 0;
  for (const auto& m : ne::methods()) {
    if (m.channels != 2) continue;
    const std::uint32_t signs = m.id == ne::method_id::xy_sign ? 2 : 1;
    std::int64_t unit = 0, nonunit = 0, nonfinite = 0, behind = 0;
    std::vector<std::tuple<long long, long long, long long>> distinct;
    std::string first_nan;
    for (std::uint32_t s = 0; s < signs; ++s)
      for (std::uint32_t y = 0; y < 256; ++y)
        for (std::uint32_t x = 0; x < 256; ++x) {
          const ne::code q{{x, y, s}};
          const ne::vec3 d = m.decode(q, bits8);
          ++total;
          if (!ne::finite(d)) {
            ++nonfinite;
            if (first_nan.empty()) first_nan = name(m) + ": code " + code_text(m, q) + " => " + vec_text(d);
            continue;
          }
          if (std::fabs(ne::length(d) - 1) <= 1e-9)
            ++unit;
          else
            ++nonunit;
          if (m.front_hemisphere && d.z < 0) ++behind;
          const ne::vec3 u = ne::normalize(d);
          if (ne::finite(u))
            distinct.emplace_back(std::llround(u.x * 1e9), std::llround(u.y * 1e9), std::llround(u.z * 1e9));
        }
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    o.figures.push_back(fig(name(m) + ".unit", unit));
    o.figures.push_back(fig(name(m) + ".not_unit", nonunit));
    o.figures.push_back(fig(name(m) + ".nan_inf", nonfinite));
    if (m.front_hemisphere || m.id == ne::method_id::xy) o.figures.push_back(fig(name(m) + ".z_below_0", behind));
    o.figures.push_back(fig(name(m) + ".distinct_directions", static_cast<std::int64_t>(distinct.size())));
    if (!first_nan.empty() && o.witnesses.size() < witness_cap) o.witnesses.push_back(first_nan);
  }
  o.domain_size = total;
  o.note =
      "per method: how the 65 536 codes (#2: 131 072) decode; NaN codes come from sqrt of a negative "
      "(the corners outside the unit disc); octahedral's codes are all unit after its normalise";
  return o;
}

outcome normal_encoding_worst_case(const gs::model_options&, const sweep_config& cfg) {
  // The supremum over the whole sphere (#8: its front hemisphere) of the angle between n and
  // decode(encode(n)) at 2×8 (xyz 3×8), from the rounding cells (cells.hpp), with the n that
  // approaches it; checked against the 2^16-point area-uniform set (its max must not exceed it).
  outcome o;
  o.result = verdict::bound;
  std::uint64_t cells = 0;
  bool sampled_ok = true;
  for (const auto& m : ne::methods()) {
    const auto& cm = cell_method(m) ? m : ne::method_of(ne::method_id::octahedral);
    const ne::worst_case w = ne::cell_worst_case(cm, bits8, cfg.threads);
    cells += w.cells;
    double sampled = 0;
    for (std::uint64_t k = 0; k < uniform_points; ++k) {
      const ne::vec3 n = ne::fibonacci_point(k, uniform_points);
      if (m.front_hemisphere && n.z < 0) continue;
      const ne::code q = m.encode(n, bits8);
      const ne::vec3 d = m.decode(q, bits8);
      if (ne::finite(d)) sampled = std::max(sampled, ne::angle(d, n) * deg);
    }
    if (sampled > w.upper_deg + 1e-9) sampled_ok = false;
    o.figures.push_back(fig_real(name(m) + ".sup_deg", w.sup_deg));
    if (w.branch_and_bound) o.figures.push_back(fig_real(name(m) + ".upper_deg", w.upper_deg));
    o.figures.push_back(fig_real(name(m) + ".sampled_max_deg", sampled));
    o.figures.push_back(fig(name(m) + ".cells_nan_decode", static_cast<std::int64_t>(w.nonfinite_cells)));
    const ne::code wq = m.encode(w.witness, bits8);
    const double wa = ne::angle(m.decode(wq, bits8), w.witness) * deg;
    std::string line = name(m) + ": n = " + vec_text(w.witness) + " => code " + code_text(m, wq) + ", " + num(wa) + "°";
    if (m.id == ne::method_id::octahedral_precise)
      line += " (bound: octahedral's cells; this n, nearest, is what precise improves)";
    o.witnesses.push_back(line);
    if (w.nonfinite_cells > 0)
      o.witnesses.push_back(name(m) + ": n = " + vec_text(w.nonfinite_n) + " => code " +
                            code_text(m, m.encode(w.nonfinite_n, bits8)) + " => NaN");
  }
  o.domain_size = cells;
  if (!sampled_ok) {
    o.result = verdict::refuted;
    o.note = "a sampled direction exceeds its method's rounding-cell supremum: the cell analysis is wrong";
  } else {
    o.note =
        "sup over every rounding cell (planar methods exact, Lambert family by branch and bound to 1e-10 rad; "
        "octahedral-precise: octahedral's sup is its upper bound); the 2^16 Fibonacci points never exceed it; "
        "cells whose code decodes to NaN are counted apart (sup excludes them)";
  }
  return o;
}

outcome normal_encoding_mean_rms(const gs::model_options&, const sweep_config&) {
  // Mean and RMS angle over the 2^16-point spherical Fibonacci set (area-uniform), 2×8 (xyz 3×8);
  // #8 and #1 over the front hemisphere too (the seed's view-space use), NaN results counted apart.
  outcome o;
  o.result = verdict::bound;
  for (const auto& m : ne::methods()) {
    double sum = 0, sum2 = 0;
    std::int64_t n_ok = 0, n_nan = 0;
    for (std::uint64_t k = 0; k < uniform_points; ++k) {
      const ne::vec3 n = ne::fibonacci_point(k, uniform_points);
      if (m.front_hemisphere && n.z < 0) continue;
      const double a = ne::angle(m.decode(m.encode(n, bits8), bits8), n) * deg;
      if (std::isnan(a)) {
        ++n_nan;
        continue;
      }
      sum += a;
      sum2 += a * a;
      ++n_ok;
    }
    o.figures.push_back(fig_real(name(m) + ".mean_deg", sum / static_cast<double>(n_ok)));
    o.figures.push_back(fig_real(name(m) + ".rms_deg", std::sqrt(sum2 / static_cast<double>(n_ok))));
    if (n_nan > 0) o.figures.push_back(fig(name(m) + ".nan", n_nan));
  }
  o.domain_size = uniform_points;
  o.note =
      "z_k = 1 − (2k+1)/N, φ_k = 2π·frac(k(√5−1)/2), N = 65 536: each point an equal-area slice; view-space over z >= "
      "0 only";
  return o;
}

outcome normal_encoding_equivalence(const gs::model_options&, const sweep_config&) {
  // 2010: for unit n, #4 sphere map, #5 CryEngine 3 and #6 Lambert are one mapping. Encoders: the
  // largest |enc_i − enc_lambert| over the area-uniform set (poles excluded: #5's normalize(0)); and
  // how many of those n get a different 8-bit code. Decoders: the largest |dec_i − dec_lambert| over
  // all 65 536 codes with a finite Lambert decode, and the codes where exactly one is NaN.
  constexpr double tolerance = 1e-12;
  double enc_dev = 0, dec_dev = 0;
  std::int64_t code_diff_sph = 0, code_diff_cry = 0, nan_mismatch = 0, poles = 0;
  const auto& sph = ne::method_of(ne::method_id::spheremap);
  const auto& cry = ne::method_of(ne::method_id::cryengine3);
  const auto& lam = ne::method_of(ne::method_id::lambert);
  std::string first_diff;
  for (std::uint64_t k = 0; k < uniform_points; ++k) {
    const ne::vec3 n = ne::fibonacci_point(k, uniform_points);
    if (n.x == 0 && n.y == 0) {
      ++poles;
      continue;
    }
    double lx, ly, sx, sy, cx, cy;
    ne::lambert::enc(n, lx, ly);
    ne::spheremap::enc(n, sx, sy);
    ne::cryengine3::enc(n, cx, cy);
    enc_dev = std::max({enc_dev, std::fabs(sx - lx), std::fabs(sy - ly), std::fabs(cx - lx), std::fabs(cy - ly)});
    const ne::code ql = lam.encode(n, bits8);
    if (!(sph.encode(n, bits8) == ql)) {
      ++code_diff_sph;
      if (first_diff.empty())
        first_diff = "n = " + vec_text(n) + ": spheremap code differs from lambert " + code_text(lam, ql);
    }
    if (!(cry.encode(n, bits8) == ql)) {
      ++code_diff_cry;
      if (first_diff.empty())
        first_diff = "n = " + vec_text(n) + ": cryengine3 code differs from lambert " + code_text(lam, ql);
    }
  }
  for (std::uint32_t y = 0; y < 256; ++y)
    for (std::uint32_t x = 0; x < 256; ++x) {
      const ne::code q{{x, y, 0}};
      const ne::vec3 l = lam.decode(q, bits8), s = sph.decode(q, bits8), c = cry.decode(q, bits8);
      const bool fl = ne::finite(l);
      if (fl != ne::finite(s) || fl != ne::finite(c)) {
        ++nan_mismatch;
        continue;
      }
      if (!fl) continue;
      dec_dev = std::max({dec_dev, ne::length(s - l), ne::length(c - l)});
    }
  outcome o;
  o.result = enc_dev <= tolerance && dec_dev <= tolerance && nan_mismatch == 0 ? verdict::proven : verdict::refuted;
  o.domain_size = uniform_points + 65536;
  o.figures = {fig_real("encoder_max_abs_diff", enc_dev),
               fig_real("decoder_max_diff", dec_dev),
               fig("codes_differ.spheremap", code_diff_sph),
               fig("codes_differ.cryengine3", code_diff_cry),
               fig("nan_decode_mismatch", nan_mismatch),
               fig("poles_skipped", poles),
               fig_real("tolerance", tolerance)};
  if (!first_diff.empty()) o.witnesses.push_back(first_diff);
  o.note =
      "algebra: both encoders are n.xy/sqrt(8(1+z)) + 1/2 and all three decoders (4a·sqrt(1−4|a|²), 1−8|a|²) for unit "
      "n; "
      "checked in double to the tolerance (not a proof for float shaders); they differ only at the poles "
      "(claim normal-encoding.singularities)";
  return o;
}

outcome normal_encoding_singularities(const gs::model_options&, const sweep_config&) {
  // Every method on the 6 axis directions and the 8 octant diagonals (exact unit inputs; #8 over
  // its front hemisphere): counterexamples are inputs whose decode(encode(n)) is NaN/Inf or more
  // than 90° away from n. Plus octahedral's (0, 0, 0) and #8's view along y.
  outcome o;
  std::vector<ne::vec3> inputs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const double r = 1 / std::sqrt(3.0);
  for (int s = 0; s < 8; ++s) inputs.push_back({s & 1 ? -r : r, s & 2 ? -r : r, s & 4 ? -r : r});
  tally t;
  std::vector<std::string> lines;
  std::uint64_t index = 0;
  for (const auto& m : ne::methods()) {
    bool first = true;  // one witness per method
    for (const auto& n : inputs) {
      if (m.front_hemisphere && n.z < 0) {
        ++index;
        continue;
      }
      const ne::code q = m.encode(n, bits8);
      const double a = ne::angle(m.decode(q, bits8), n) * deg;
      if (std::isnan(a) || a > 90) {
        if (first)
          lines.push_back(name(m) + ": n = " + vec_text(n) + " => code " + code_text(m, q) + " => " +
                          (std::isnan(a) ? std::string("NaN") : num(a) + "°"));
        first = false;
        t.add(index);
      }
      ++index;
    }
  }
  o.result = t.count == 0 ? verdict::proven : verdict::refuted;
  o.domain_size = index;
  o.counterexamples = t.count;
  o.witnesses = lines;
  const ne::vec3 zero_oct = ne::method_of(ne::method_id::octahedral)
                                .decode(ne::method_of(ne::method_id::octahedral).encode({0, 0, 0}, bits8), bits8);
  o.figures = {fig("octahedral.zero_input_decodes_finite", ne::finite(zero_oct) ? 1 : 0)};
  o.note =
      "NaN or > 90° on an axis or diagonal: #1 (0,0,−1) decodes to +z; #1/#2/#8 (±1,0,0), (0,±1,0) hit codes outside "
      "the unit disc "
      "(sqrt < 0); sphere map/Lambert 0/0 at (0,0,−1); CryEngine 3 normalize(0) at both poles (and stereographic 0/0 "
      "at (0,0,−1), stored as code (0, 0): 43° off, not counted)";
  return o;
}

outcome normal_encoding_xy_wrong_sign(const gs::model_options&, const sweep_config&) {
  // #1 stores no sign of z: every n with z < 0 decodes with z >= 0 (or NaN) — half the sphere by
  // area (Archimedes: the area of z < 0 is 2π of 4π). Measured on the area-uniform set at 2×8:
  // the share decoded with the wrong z sign, the share NaN, and the share more than 10° off.
  const auto& m = ne::method_of(ne::method_id::xy);
  std::int64_t wrong = 0, nan = 0, far = 0;
  for (std::uint64_t k = 0; k < uniform_points; ++k) {
    const ne::vec3 n = ne::fibonacci_point(k, uniform_points);
    const ne::vec3 d = m.decode(m.encode(n, bits8), bits8);
    if (!ne::finite(d)) {
      ++nan;
      continue;
    }
    if ((n.z < 0) != (d.z < 0) && n.z != 0 && d.z != 0) ++wrong;
    if (ne::angle(d, n) * deg > 10) ++far;
  }
  outcome o;
  o.result = verdict::bound;
  o.domain_size = uniform_points;
  const double nn = static_cast<double>(uniform_points);
  o.figures = {fig("wrong_z_sign", wrong),
               fig("nan", nan),
               fig("over_10_deg", far),
               fig_real("share_wrong_z_sign", wrong / nn),
               fig_real("share_nan", nan / nn),
               fig_real("share_over_10_deg", far / nn),
               fig_real("share_exact_area_z_below_0", 0.5)};
  o.note =
      "the wrong-sign share is the z < 0 half of the sphere (exactly 1/2 by area); a sliver near the equator decodes "
      "NaN instead";
  return o;
}

outcome normal_encoding_2009_vs_2010(const gs::model_options&, const sweep_config&) {
  // The 2009 encoders did not normalise their (interpolated) input. Interpolating two unit normals
  // 2α apart at their midpoint gives length cos α; we feed n·ℓ for ℓ = cos 10° (2α = 20°) and
  // ℓ = cos 30° over the area-uniform set and compare the mean angle with the 2010 encoders
  // (normalise first), 2×8.
  outcome o;
  o.result = verdict::bound;
  const double ls[2] = {std::cos(10 / deg), std::cos(30 / deg)};
  const char* tag[2] = {"len_cos10", "len_cos30"};
  for (const auto& m : ne::methods()) {
    for (int li = 0; li < 2; ++li) {
      double s09 = 0, s10 = 0;
      std::int64_t c09 = 0, c10 = 0;
      for (std::uint64_t k = 0; k < uniform_points; k += 4) {
        const ne::vec3 n = ne::fibonacci_point(k, uniform_points);
        if (m.front_hemisphere && n.z < 0) continue;
        const ne::vec3 in = ls[li] * n;
        const double a09 = ne::angle(m.decode(m.encode(in, bits8), bits8), n) * deg;
        const double a10 = ne::angle(m.decode(ne::encode_2010(m, in, bits8), bits8), n) * deg;
        if (!std::isnan(a09)) {
          s09 += a09;
          ++c09;
        }
        if (!std::isnan(a10)) {
          s10 += a10;
          ++c10;
        }
      }
      o.figures.push_back(fig_real(name(m) + "." + tag[li] + ".mean_deg_2009", s09 / static_cast<double>(c09)));
      o.figures.push_back(fig_real(name(m) + "." + tag[li] + ".mean_deg_2010", s10 / static_cast<double>(c10)));
    }
  }
  o.domain_size = uniform_points / 4 * 2;
  o.note =
      "octahedral (n/(|x|+|y|+|z|)) and the direction-only encoders (spherical's atan2, CryEngine 3's normalize(xy)) "
      "are partly or fully scale-invariant; the others shrink toward the centre or misplace z";
  return o;
}

outcome normal_encoding_ranking(const gs::model_options&, const sweep_config& cfg) {
  // The methods ranked by worst case over the sphere at 2×8 (NaN-reaching counted as worst) and by
  // the published PSNR (2009 table; 2010 table), on the methods both tables have.
  struct row {
    ne::method_id id;
    double psnr09, psnr10;
  };
  const row rows[] = {{ne::method_id::xy, 15.054, 18.692},
                      {ne::method_id::spherical, 40.244, 42.042},
                      {ne::method_id::spheremap, 44.781, 48.071},
                      {ne::method_id::stereographic, 44.207, 44.147}};
  outcome o;
  o.result = verdict::bound;
  std::vector<std::pair<double, std::string>> by_worst, by09, by10;
  for (const auto& r : rows) {
    const auto& m = ne::method_of(r.id);
    const auto w = ne::cell_worst_case(m, bits8, cfg.threads);
    const double key = w.nonfinite_cells > 0 ? 1000 + w.sup_deg : w.sup_deg;
    by_worst.push_back({key, name(m)});
    by09.push_back({-r.psnr09, name(m)});
    by10.push_back({-r.psnr10, name(m)});
    o.figures.push_back(fig_real(name(m) + ".worst_deg", w.sup_deg));
    o.figures.push_back(fig(name(m) + ".reaches_nan", w.nonfinite_cells > 0 ? 1 : 0));
  }
  auto order = [](auto v) {
    std::sort(v.begin(), v.end());
    std::string s;
    for (const auto& [k, n] : v) s += (s.empty() ? "" : " > ") + n;
    return s;
  };
  o.witnesses = {"best first by worst case (NaN-reaching last): " + order(by_worst), "by PSNR 2009: " + order(by09),
                 "by PSNR 2010: " + order(by10)};
  o.domain_size = std::size(rows);
  o.note =
      "the PSNR tables rank the sphere map first; over the whole sphere it reaches NaN near (0,0,−1) and "
      "11.5° beside it, and spherical's worst case is the smallest of the four";
  return o;
}

}  // namespace gsdot3::proofs::claims
