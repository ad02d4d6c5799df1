// Seed 002 (Pranckevičius 2009, "Compact Normal Storage for small G-Buffers"), its 2010 revision and
// octahedral encoding: every 2×8 code, the worst case over the whole sphere from the rounding cells
// (src/schemes/normal_encoding/cells.hpp), means over an area-uniform set, and the sphere map =
// CryEngine 3 = Lambert equivalence; singularities, the 2009/2010 encoders and the ranking are
// claims_normal_encoding_defects.cpp.
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
#include "proofs/normal_encoding_text.hpp"

namespace gsdot3::proofs::claims {

namespace ne = normal_encoding;
using namespace encoding_text;  // the seed-002 claims' shared vocabulary

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
    std::string line =
        name(m) + ": n = " + vec_text(w.witness) + " => code " + code_text(m, wq) + ", " + real_text(wa) + "°";
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

}  // namespace gsdot3::proofs::claims
