// proofs/valve_sweeps.cpp — see valve_sweeps.hpp.
#include "proofs/valve_sweeps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "proofs/verdict.hpp"

#include "valve/decode.hpp"
#include "valve/encode.hpp"
#include "valve/evaluate.hpp"

namespace gsdot3::proofs::valve_sweeps {

namespace v = gsdot3::valve;

std::uint32_t texel_domain::rgb(std::uint64_t i) const noexcept {
  const std::uint64_t n = values.size();
  return (std::uint32_t{values[i / (n * n)]} << 16) | (std::uint32_t{values[(i / n) % n]} << 8) | values[i % n];
}

texel_domain texel_domain::all() {
  texel_domain d;
  for (int c = 0; c < 256; ++c) d.values.push_back(static_cast<std::uint8_t>(c));
  d.description = "every RGB8 texel (2^24)";
  return d;
}

texel_domain texel_domain::catalogue() {
  texel_domain d;
  for (int c = 0; c < 256; c += 4) d.values.push_back(static_cast<std::uint8_t>(c));
  d.values.push_back(255);
  d.description = "every texel with r, g, b ∈ {0, 4, …, 252, 255} (65³)";
  return d;
}

double stat::rmse() const noexcept { return n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0; }

namespace {

constexpr v::lightmaps unit_light[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

double component(const v::vec3<double>& d, int i) noexcept { return i == 0 ? d.x : i == 1 ? d.y : d.z; }

double angle_degrees(const v::vec3<double>& a, const v::vec3<double>& b) noexcept {
  return std::acos(std::clamp(v::dot(a, b), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// sign(u + v·√2) for integers (exact: √2 is irrational, so u + v√2 = 0 only for u = v = 0).
int sign_root2(std::int64_t u, std::int64_t w) noexcept {
  if (u >= 0 && w >= 0) return (u | w) != 0;
  if (u <= 0 && w <= 0) return -1;
  const std::int64_t d = u * u - 2 * w * w;  // ≠ 0 unless u = w = 0
  return u > 0 ? (d > 0 ? 1 : -1) : (d < 0 ? 1 : -1);
}

// sign(a + b·√3 + c·√2) for integers, exactly: p = a + c√2, then p + b√3 by p² − 3b² =
// (a² + 2c² − 3b²) + 2ac·√2.
int sign_root3_root2(std::int64_t a, std::int64_t b, std::int64_t c) noexcept {
  const int sp = sign_root2(a, c);
  if (sp >= 0 && b >= 0) return sp > 0 || b > 0;
  if (sp <= 0 && b <= 0) return -(sp < 0 || b < 0);
  const int s = sign_root2(a * a + 2 * c * c - 3 * b * b, 2 * a * c);
  return sp > 0 ? s : -s;
}

}  // namespace

true_normal_result true_normal_sweep(double step) {
  const v::shader_arith a32{v::precision::fp32};
  true_normal_result r;
  for (double th = 0; th <= 90.0 + 1e-9; th += step)
    for (double ph = 0; ph < 360.0 - 1e-9; ph += step) {
      const double t = th * std::numbers::pi / 180, p = ph * std::numbers::pi / 180;
      const v::vec3<double> n{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
      v::vec3<double> D;
      if (!v::exact_weights(n, D)) continue;
      const v::texel rgb = v::encode_normal_rgb8(n);
      const v::texel ideal{v::to_unorm8(D.x, v::quantise::nearest), v::to_unorm8(D.y, v::quantise::nearest),
                           v::to_unorm8(D.z, v::quantise::nearest)};
      const v::texel source = v::ssbump_texel(v::normal2ssbump(rgb));
      for (int l = 0; l < 3; ++l) {
        const double want = component(D, l);
        r.rnm_fp32.add(std::fabs(v::rnm_diffuse(a32, rgb, unit_light[l]) - want) * 255.0, r.samples);
        r.ssbump_ideal.add(std::fabs(v::ssbump_diffuse(a32, ideal, unit_light[l]) - want) * 255.0, r.samples);
        r.ssbump_source.add(std::fabs(v::ssbump_diffuse(a32, source, unit_light[l]) - want) * 255.0, r.samples);
      }
      ++r.samples;
    }
  return r;
}

precision_result precision_sweep(const texel_domain& dom, const sweep_config& cfg) {
  const v::shader_arith a32{v::precision::fp32}, a24{v::precision::fp24};
  const double unit_tol = std::sqrt(3.0) / 255.0;  // | |N| − 1 | of round(127.5·n + 127.5) for unit n
  auto acc = sweep<precision_result>(dom.size(), cfg, [&](precision_result& r, std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i) {
      ++r.domain;
      const v::texel t = v::texel::at(dom.rgb(i));
      const v::vec3<double> N = v::encoded_normal(t), U = v::normalised(N);
      v::vec3<double> D;
      if (!v::exact_weights(U, D)) {
        ++r.zero_sum;
        continue;
      }
      const bool unit = std::fabs(std::sqrt(v::dot(N, N)) - 1.0) <= unit_tol;
      r.unit_texels += unit;
      const v::vec3<float> tool = v::normal2ssbump(t);
      const v::texel s_trunc = v::ssbump_texel(tool), s_near = v::ssbump_texel(tool, v::quantise::nearest);
      if (v::ssbump_texel(v::normal2ssbump(t, v::exact_basis_float)) != s_trunc) ++r.literal_changes;
      for (int l = 0; l < 3; ++l) {
        const double want = component(D, l);
        const double got[4] = {v::rnm_diffuse(a32, t, unit_light[l]), v::rnm_diffuse(a24, t, unit_light[l]),
                               v::ssbump_diffuse(a32, s_trunc, unit_light[l]),
                               v::ssbump_diffuse(a32, s_near, unit_light[l])};
        for (int p = 0; p < 4; ++p) {
          if (std::isnan(got[p])) {
            r.nan[p] += l == 0;
            continue;
          }
          const double e = std::fabs(got[p] - want) * 255.0;
          r.err[p][0].add(e, i);
          if (unit) r.err[p][1].add(e, i);
        }
      }
      const v::vec3<double> W = v::ssbump_weights(v::shader_arith{v::precision::exact}, s_trunc);
      const bool cone =
          v::dot(U, v::exact_basis[0]) >= 0 && v::dot(U, v::exact_basis[1]) >= 0 && v::dot(U, v::exact_basis[2]) >= 0;
      if (W.x + W.y + W.z == 0) continue;
      const double ang[2] = {angle_degrees(v::reconstruct_normal(W), U),
                             angle_degrees(v::reconstruct_normal_sqrt(W), U)};
      for (int k = 0; k < 2; ++k) {
        r.reconstruct[k][0].add(ang[k], i);
        if (cone) r.reconstruct[k][1].add(ang[k], i);
      }
    }
  });
  return acc;
}

void precision_result::merge(const precision_result& later) {
  domain += later.domain, zero_sum += later.zero_sum, unit_texels += later.unit_texels;
  literal_changes += later.literal_changes;
  for (int p = 0; p < 4; ++p) nan[p] += later.nan[p];
  for (int p = 0; p < 4; ++p)
    for (int k = 0; k < 2; ++k) err[p][k].merge(later.err[p][k]);
  for (int p = 0; p < 2; ++p)
    for (int k = 0; k < 2; ++k) reconstruct[p][k].merge(later.reconstruct[p][k]);
}

void zero_sum_result::merge(const zero_sum_result& later) {
  domain += later.domain, exact += later.exact, fp32 += later.fp32, fp24 += later.fp24;
  not_nan_fp32 += later.not_nan_fp32, not_nan_fp24 += later.not_nan_fp24, tool_not_nan += later.tool_not_nan;
  for (auto w : later.first)
    if (first.size() < witness_cap) first.push_back(w);
}

zero_sum_result zero_sum_sweep(const sweep_config& cfg) {
  const v::shader_arith a32{v::precision::fp32}, a24{v::precision::fp24};
  // The shader's d_i = saturate(dp3)² is 0 iff its rounded dp3 ≤ 0. Its dp3 differs from the exact
  // N·B_i by less than 1e-3 (three products and two sums of magnitude ≤ 1.5, each rounded to ≥ 17
  // bits, plus the texel's and the constants' rounding: < 10 · 1.5 · 2^-17 ≈ 1.2e-4), so a texel with
  // some exact N·B_i > 1e-3 has a non-zero shader sum; only the others are evaluated in the shader.
  auto shader_zero = [](const v::shader_arith& a, const v::texel& t) {
    const v::vec3<double> N = v::rnm_normal(a, t);
    for (const auto& b : v::source_basis)
      if (a.dp3(N.x, N.y, N.z, a.r(b.x), a.r(b.y), a.r(b.z)) > 0) return false;
    return true;
  };
  return sweep<zero_sum_result>(1U << 24, cfg, [&](zero_sum_result& r, std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i) {
      ++r.domain;
      const v::texel t = v::texel::at(static_cast<std::uint32_t>(i));
      const std::int64_t X = 2 * t.r - 255, Y = 2 * t.g - 255, Z = 2 * t.b - 255;  // 255·N, odd integers
      // √6·255·N·B: B0 → 2X + √2·Z; B1 → −X + √3·Y + √2·Z; B2 → −X − √3·Y + √2·Z. None is 0.
      const bool exact = sign_root2(2 * X, Z) < 0 && sign_root3_root2(-X, Y, Z) < 0 && sign_root3_root2(-X, -Y, Z) < 0;
      const v::vec3<double> N = v::encoded_normal(t);
      const double top =
          std::max({v::dot(N, v::exact_basis[0]), v::dot(N, v::exact_basis[1]), v::dot(N, v::exact_basis[2])});
      bool z32 = false, z24 = false;
      if (top <= 1e-3) z32 = shader_zero(a32, t), z24 = shader_zero(a24, t);
      r.fp32 += z32, r.fp24 += z24;
      if (!exact) continue;
      ++r.exact;
      if (r.first.size() < witness_cap) r.first.push_back(static_cast<std::uint32_t>(i));
      r.not_nan_fp32 += !std::isnan(v::rnm_diffuse(a32, t, {1, 1, 1}));
      r.not_nan_fp24 += !std::isnan(v::rnm_diffuse(a24, t, {1, 1, 1}));
      if (!std::isnan(v::normal2ssbump(t).x)) ++r.tool_not_nan;
    }
  });
}

void filtering_result::merge(const filtering_result& later) {
  texels = std::max(texels, later.texels);
  pairs += later.pairs;
  for (int w = 0; w < 15; ++w) by_weight[w].merge(later.by_weight[w]);
  if (later.all.max > all.max) worst_a = later.worst_a, worst_b = later.worst_b, worst_w = later.worst_w;
  all.merge(later.all);
  near.merge(later.near);
  over_half += later.over_half, over_one += later.over_one;
}

filtering_result rnm_filtering_sweep(int grid, const sweep_config& cfg) {
  std::vector<v::texel> set;
  for (int i = 0; i <= grid; ++i)
    for (int j = 0; j <= grid; ++j) {
      const double x = -1.0 + 2.0 * i / grid, y = -1.0 + 2.0 * j / grid, zz = 1.0 - x * x - y * y;
      if (zz < 0) continue;
      const v::texel t = v::encode_normal_rgb8({x, y, std::sqrt(zz)});
      if (std::find(set.begin(), set.end(), t) == set.end()) set.push_back(t);
    }
  std::vector<v::vec3<double>> N(set.size()), D(set.size());
  std::vector<char> ok(set.size());
  for (std::size_t k = 0; k < set.size(); ++k) N[k] = v::encoded_normal(set[k]), ok[k] = v::exact_weights(N[k], D[k]);
  auto r = sweep<filtering_result>(set.size(), cfg, [&](filtering_result& acc, std::uint64_t begin, std::uint64_t end) {
    acc.texels = set.size();
    for (std::uint64_t a = begin; a < end; ++a)
      for (std::size_t b = a + 1; b < set.size(); ++b) {
        if (!ok[a] || !ok[b]) continue;
        ++acc.pairs;
        const bool is_near = angle_degrees(v::normalised(N[a]), v::normalised(N[b])) <= 10.0;
        for (int w = 1; w <= 15; ++w) {
          const double wa = (16 - w) / 16.0, wb = w / 16.0;
          // The filtered texel decodes to the filtered normal (2t − 1 is affine).
          const v::vec3<double> Nf{wa * N[a].x + wb * N[b].x, wa * N[a].y + wb * N[b].y, wa * N[a].z + wb * N[b].z};
          v::vec3<double> Df;
          if (!v::exact_weights(Nf, Df)) continue;
          double e = 0;
          for (int l = 0; l < 3; ++l)
            e = std::max(e, std::fabs(component(Df, l) - (wa * component(D[a], l) + wb * component(D[b], l))) * 255.0);
          const std::uint64_t index = (a * set.size() + b) * 16 + static_cast<std::uint64_t>(w);
          if (e > acc.all.max) acc.worst_a = set[a].index(), acc.worst_b = set[b].index(), acc.worst_w = w;
          acc.all.add(e, index);
          acc.by_weight[w - 1].add(e, index);
          if (is_near) acc.near.add(e, index);
          acc.over_half += e > 0.5, acc.over_one += e > 1.0;
        }
      }
  });
  r.texels = set.size();
  return r;
}

}  // namespace gsdot3::proofs::valve_sweeps
