// Sections 3.6 - 3.8: HIGHLIGHT attenuation, specular power compensation, and the two-pass /
// four-pass level-of-detail switch.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/domains.hpp"
#include "proofs/four_pass.hpp"
#include "proofs/methods.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;

outcome highlight_attenuation(const gs::model_options& o, const sweep_config&) {
  // 128 − (128 − sph)·scale = sph·scale + (1 − scale)·128 via HIGHLIGHT: vertex RGB = k = 128·scale,
  // vertex A = 128 − k. Error in 1/128 units: 128·GS − (128·128 − (128 − sph)·k), exact integers.
  extremes err;
  std::uint64_t clamps = 0, index = 0;
  for (int sph = 0; sph < 256; ++sph)
    for (int k = 0; k <= 128; ++k, ++index) {
      const auto colour = gs::fragment_colour::flat({m::byte(k), m::byte(k), m::byte(k), m::byte(128 - k)});
      const auto c = gs::texture_function(gs::tfx::HIGHLIGHT, gs::tcc::RGB, m::grey(sph, 0), colour, o);
      if (gs::modulate_channel(m::byte(sph), colour.r, o).value() + (128 - k) > 255) ++clamps;
      err.add(128 * c.r.value() - (128 * 128 - (128 - sph) * k), index);
    }
  auto at = [](std::uint64_t i) {
    const int sph = static_cast<int>(i / 129), k = static_cast<int>(i % 129);
    return "sph = " + hexdec(sph) + ", k = " + hexdec(k);
  };
  outcome out;
  out.result = verdict::bound;
  out.domain_size = index;
  out.figures = {fig("err_min_128ths", err.min), fig("err_max_128ths", err.max), fig_real("err_min", err.min / 128.0),
                 fig_real("err_max", err.max / 128.0), fig("clamps", static_cast<std::int64_t>(clamps))};
  out.witnesses = {"err_min at " + at(err.arg_min), "err_max at " + at(err.arg_max)};
  out.note =
      "HIGHLIGHT floors sph·k/128, so the attenuated texel is up to 127/128 below the exact value "
      "(the signed vector up to 127/128 longer); the clamp never bites";
  return out;
}

outcome spot_attenuation_blend(const gs::model_options& o, const sweep_config&) {
  // Section 3.6: a spot light's intensity texel a = 128·scale attenuates a DPB channel d by the blend
  // (Cd − Cs)·As + Cs (methods::spot_attenuate), "in the same way as" HIGHLIGHT attenuates the sphere
  // map in pass 1 (vertex RGB = a, vertex alpha = 128 − a). (1) Every d × a: the blend's channel
  // against HIGHLIGHT's (a counterexample where they differ) and against the exact 128 − (128 − d)·a/128.
  // (2) The two placements per channel, against the unattenuated four-pass product p = product(s, b)
  // (four_pass::table: sphere component s, normal component b) scaled exactly, a·p/128: after pass 1 the
  // DPB byte 128 − s is attenuated before the signed multiply; after the four passes the channel
  // 128 + p is. Errors in 1/128 of a DPB step.
  const four_pass::table t4(o);
  auto blended = [&](int d, int a) {
    return static_cast<int>(m::spot_attenuate(m::grey(d, 0).to_u32(), m::byte(a), o) & 0xFF);
  };
  extremes exact, after1, after4;
  std::uint64_t differ = 0, index = 0;
  std::vector<std::string> witnesses;
  for (int d = 0; d < 256; ++d)
    for (int a = 0; a <= 128; ++a, ++index) {
      const int blend = blended(d, a);
      const auto colour = gs::fragment_colour::flat({m::byte(a), m::byte(a), m::byte(a), m::byte(128 - a)});
      const int highlight = gs::texture_function(gs::tfx::HIGHLIGHT, gs::tcc::RGB, m::grey(d, 0), colour, o).r.value();
      exact.add(128 * blend - (128 * 128 - (128 - d) * a), index);
      if (blend != highlight && ++differ <= 4)
        witnesses.push_back("DPB channel " + hexdec(d) + ", As " + hexdec(a) + " => blend " + hexdec(blend) +
                            ", HIGHLIGHT " + hexdec(highlight));
    }
  const std::uint64_t first = index;
  for (int sph = -127; sph <= 128; ++sph)
    for (int b = -128; b <= 127; ++b)
      for (int a = 0; a <= 128; ++a, ++index) {
        const int p = t4.product(sph, b);
        const int p1 = t4.product(128 - blended(128 - sph, a), b), p4 = blended(128 + p, a) - 128;
        after1.add(128 * p1 - a * p, index), after4.add(128 * p4 - a * p, index);
      }
  auto at = [&](std::uint64_t i) {
    if (i < first)
      return "DPB channel " + hexdec(static_cast<int>(i / 129)) + ", As " + hexdec(static_cast<int>(i % 129));
    const std::uint64_t k = i - first;
    const int sph = static_cast<int>(k / (256 * 129)) - 127, b = static_cast<int>(k / 129 % 256) - 128;
    return "sphere s = " + std::to_string(sph) + " (DPB " + hexdec(128 - sph) + "), normal b = " + std::to_string(b) +
           " (alpha " + hexdec(b + 128) + "), As " + hexdec(static_cast<int>(k % 129));
  };
  outcome out;
  out.result = differ == 0 ? verdict::proven : verdict::refuted;
  out.counterexamples = differ;
  out.domain_size = index;
  out.figures = {fig("err_min_128ths", exact.min),
                 fig("err_max_128ths", exact.max),
                 fig("after_pass1_err_min_128ths", after1.min),
                 fig("after_pass1_err_max_128ths", after1.max),
                 fig("after_pass4_err_min_128ths", after4.min),
                 fig("after_pass4_err_max_128ths", after4.max)};
  witnesses.insert(witnesses.end(),
                   {"err_min at " + at(exact.arg_min), "err_max at " + at(exact.arg_max),
                    "after_pass1_err_min at " + at(after1.arg_min), "after_pass1_err_max at " + at(after1.arg_max),
                    "after_pass4_err_min at " + at(after4.arg_min), "after_pass4_err_max at " + at(after4.arg_max)});
  out.witnesses = std::move(witnesses);
  out.note =
      "the blend (Cd − Cs)·As + Cs with Cs = 128 gives HIGHLIGHT's channel wherever the blend's >> 7 floors as "
      "HIGHLIGHT's product does; per channel, attenuating after pass 1 passes the rounding through the signed "
      "multiply, after the four passes it rounds the product once (a dot sums three channels)";
  return out;
}

outcome specular_attenuation_compensation(const gs::model_options& o, const sweep_config&) {
  // Model (section 3.7): the diffuse ILP holds i + 1 at dot index i (so index i stands for dot
  // (i + 1)/128); the specular ILP of power n holds round(128·((i + 1)/128)^n). Compensated
  // attenuation scales the dot by k = round(128·att^(1/n)) — on the GS, MODULATE of the dot byte by
  // the colour k — before the look-up; the wanted value is 128·att·((i + 1)/128)^n. The
  // uncompensated variant scales by round(128·att). Errors in ILP units (1/128 of the light).
  auto ilp = [](int n, int i) { return std::round(128.0 * std::pow((i + 1) / 128.0, n)); };
  auto scaled = [&](int i, int k) {
    return gs::texture_function(gs::tfx::MODULATE, gs::tcc::RGB, m::grey(i, 0),
                                gs::fragment_colour::flat(m::grey(k, 0x80)), o)
        .r.value();
  };
  double cmin = 1e9, cmax = -1e9, umin = 1e9, umax = -1e9;
  std::string cmin_at, cmax_at;
  std::uint64_t size = 0;
  for (int n = 2; n <= 64; ++n)
    for (int a = 0; a <= 128; ++a)
      for (int i = 0; i < 128; ++i, ++size) {
        const double att = a / 128.0, want = 128.0 * att * std::pow((i + 1) / 128.0, n);
        const int k = static_cast<int>(std::lround(128.0 * std::pow(att, 1.0 / n)));
        const double comp = ilp(n, scaled(i, k)) - want, unc = ilp(n, scaled(i, a)) - want;
        auto where = [&] {
          return "n = " + std::to_string(n) + ", att = " + std::to_string(a) + "/128, dot index " + std::to_string(i);
        };
        if (comp < cmin) cmin = comp, cmin_at = where();
        if (comp > cmax) cmax = comp, cmax_at = where();
        umin = std::min(umin, unc), umax = std::max(umax, unc);
      }
  outcome out;
  out.result = verdict::bound;
  out.domain_size = size;
  out.figures = {fig_real("err_min", cmin), fig_real("err_max", cmax), fig_real("uncompensated_err_min", umin),
                 fig_real("uncompensated_err_max", umax)};
  out.witnesses = {"err_min at " + cmin_at, "err_max at " + cmax_at};
  out.note =
      "(att^(1/n)·dot)^n through an 8-bit dot index stays within the bound shown (ILP units); without the "
      "compensation the error is the uncompensated range";
  return out;
}

outcome lod_two_vs_four(const gs::model_options& o, const sweep_config& cfg) {
  // The same 8-bit palette index means the same unit normal n̂: the four-pass palette holds
  // b = round(127·n̂) (taken from normal_map_vectors(), n̂ = b/|b|) and the two-pass palettes hold
  // Appendix 2's packing of n̂. Lights: every 64×64 sphere-map texel inside the disc; four-pass reads
  // its packed vector, two-pass gets (char)(122·L) of the texel's float unit vector L at the vertices.
  // Both dot products come from their tables (built through the model): two_pass::table (value, no
  // wrap for s = 122) and four_pass::table (sum; wraps are counted by four-pass.sum-wrap).
  const auto normals = normal_map_vectors();
  const two_pass::table t2(o);
  const four_pass::table t4(o);
  std::vector<paper::packed_normal> packed;
  for (const auto& b : normals) {
    const double len = std::sqrt(double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2]);
    packed.push_back(paper::pack_normal(static_cast<float>(b[0] / len), static_cast<float>(b[1] / len)));
  }
  struct light {
    ivec3 a, l;
  };
  std::vector<light> lights;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const auto t = paper::sphere_map_texel(x, y, 64, 64);
      if (!t.inside) continue;
      lights.push_back({{128 - t.r, 128 - t.g, 128 - t.b},
                        {paper::pack_light_component(122.0f, t.lx), paper::pack_light_component(122.0f, t.ly),
                         paper::pack_light_component(122.0f, t.lz)}});
    }
  const std::uint64_t nn = normals.size(), nl = lights.size();
  struct acc {
    extremes diff, visible;  // visible: the difference after the ILP's clamp of negative dots to 0
    void merge(const acc& l) { diff.merge(l.diff), visible.merge(l.visible); }
  };
  // Per light and channel c the pair (l_c, a_c) is one of few (the texel's float component gives
  // both), so both dot products come from one 32-bit look-up per channel: a normal's table holds, per
  // pair, (two-pass channel(n_c, l_c) + bias) << 16 | (four-pass product(a_c, b_c) + bias), and the
  // three channels' words add without a carry between the halves (each term + bias is in
  // [0, 2·bias), checked when the halves are tabulated, and 3·2·bias < 2^16). The halves are
  // tabulated per component value (n_c ∈ [−127, 128], b_c ∈ [−128, 127]), so a normal's table is one
  // addition per pair. Outer loop over normals, so a normal's tables stay in L1 while the lights run;
  // a normal whose extremes improve the running ones is walked again for the first index.
  constexpr int bias = 4096;
  std::array<std::vector<std::array<int, 2>>, 3> pairs;  // per channel: the distinct (l_c, a_c)
  std::array<std::vector<std::uint16_t>, 3> pair_of;     // per channel and light: its pair's index
  std::array<std::vector<std::uint32_t>, 3> high, low;   // per channel: [n_c + 127][pair], [b_c + 128][pair]
  auto half = [](int term) {
    if (term + bias < 0 || term + bias >= 2 * bias)
      throw std::logic_error("lod.two-vs-four: a channel's dot term outside the packed word's range");
    return static_cast<std::uint32_t>(term + bias);
  };
  for (std::size_t c = 0; c < 3; ++c) {
    for (const auto& L : lights) {
      const std::array<int, 2> key{L.l[c], L.a[c]};
      auto it = std::find(pairs[c].begin(), pairs[c].end(), key);
      if (it == pairs[c].end()) it = pairs[c].insert(pairs[c].end(), key);
      pair_of[c].push_back(static_cast<std::uint16_t>(it - pairs[c].begin()));
    }
    for (int v = 0; v < 256; ++v)
      for (const auto& [l, a] : pairs[c]) {
        high[c].push_back(half(t2.channel(v - 127, l)) << 16);
        low[c].push_back(half(t4.product(a, v - 128)));
      }
  }
  const auto r = sweep<acc>(nn, cfg, [&](acc& s, std::uint64_t lo, std::uint64_t hi) {
    std::array<std::vector<std::uint32_t>, 3> word;
    for (auto j = lo; j < hi; ++j) {
      const auto& p = packed[j];
      const auto& b = normals[j];
      const std::array<int, 3> n{p.iX, p.iY, p.iZ};
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t k = pairs[c].size();
        const std::uint32_t* h = &high[c][static_cast<std::size_t>(n[c] + 127) * k];
        const std::uint32_t* f = &low[c][static_cast<std::size_t>(b[c] + 128) * k];
        word[c].resize(k);
        for (std::size_t i = 0; i < k; ++i) word[c][i] = h[i] + f[i];
      }
      const std::uint32_t *wx = word[0].data(), *wy = word[1].data(), *wz = word[2].data();
      const std::uint16_t *kx = pair_of[0].data(), *ky = pair_of[1].data(), *kz = pair_of[2].data();
      const int base = 3 * t2.alpha(p.alpha) - 384 - 3 * bias;
      auto light = [&](std::size_t i) {  // {two − four, visible difference}
        const std::uint32_t w = wx[kx[i]] + wy[ky[i]] + wz[kz[i]];
        const int two = static_cast<int>(w >> 16) + base, four = static_cast<int>(w & 0xFFFFu) - 3 * bias;
        return std::array<int, 2>{two - four, std::max(two, 0) - std::max(four, 0)};
      };
      int vmin = INT_MAX, vmax = INT_MIN, dmin = INT_MAX, dmax = INT_MIN;
      for (std::size_t i = 0; i < nl; ++i) {
        const auto [diff, visible] = light(i);
        dmin = std::min(dmin, diff), dmax = std::max(dmax, diff);
        vmin = std::min(vmin, visible), vmax = std::max(vmax, visible);
      }
      if (dmin < s.diff.min || dmax > s.diff.max || vmin < s.visible.min || vmax > s.visible.max)
        for (std::size_t i = 0; i < nl; ++i) {
          const auto [diff, visible] = light(i);
          s.diff.add(diff, j * nl + i), s.visible.add(visible, j * nl + i);
        }
    }
  });
  auto at = [&](std::uint64_t i) {
    const auto& L = lights[i % nl];
    const auto& b = normals[i / nl];
    const auto& p = packed[i / nl];
    return "b = (" + std::to_string(b[0]) + ", " + std::to_string(b[1]) + ", " + std::to_string(b[2]) +
           "), two-pass n = (" + std::to_string(p.iX) + ", " + std::to_string(p.iY) + ", " + std::to_string(p.iZ) +
           "), sphere a = (" + std::to_string(L.a[0]) + ", " + std::to_string(L.a[1]) + ", " + std::to_string(L.a[2]) +
           "), l = (" + std::to_string(L.l[0]) + ", " + std::to_string(L.l[1]) + ", " + std::to_string(L.l[2]) +
           ") => two-pass " + std::to_string(t2.value(p, L.l)) + ", four-pass " + std::to_string(t4.dot(L.a, b));
  };
  outcome out;
  out.result = verdict::bound;
  out.domain_size = nl * nn;
  out.figures = {fig("diff_min", r.diff.min), fig("diff_max", r.diff.max), fig("visible_diff_min", r.visible.min),
                 fig("visible_diff_max", r.visible.max)};
  out.witnesses = {"diff_min at " + at(r.diff.arg_min), "diff_max at " + at(r.diff.arg_max),
                   "visible_diff_min at " + at(r.visible.arg_min), "visible_diff_max at " + at(r.visible.arg_max)};
  out.note =
      "two-pass minus four-pass dot product for the same palette index and light direction: the scales "
      "differ (128·122/128 vs 127·127/128), both round, and Appendix 2 refills iZ after truncating iX, iY, "
      "tilting grazing normals towards +z; visible_* compares the intensities after the ILP (negative dots -> 0)";
  return out;
}

}  // namespace gsdot3::proofs::claims
