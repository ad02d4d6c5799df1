// Sections 3.6 - 3.8: HIGHLIGHT attenuation, specular power compensation, and the two-pass /
// four-pass level-of-detail switch.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

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
  // [0, 2·bias), checked when the table is filled, and 3·2·bias < 2^16). Outer loop over normals, so a
  // normal's tables stay in L1 while the lights run; a normal whose extremes improve the running ones
  // is walked again for the first index.
  constexpr int bias = 4096;
  std::array<std::vector<std::array<int, 2>>, 3> pairs;  // per channel: the distinct (l_c, a_c)
  std::array<std::vector<std::uint16_t>, 3> pair_of;     // per channel and light: its pair's index
  for (std::size_t c = 0; c < 3; ++c)
    for (const auto& L : lights) {
      const std::array<int, 2> key{L.l[c], L.a[c]};
      auto it = std::find(pairs[c].begin(), pairs[c].end(), key);
      if (it == pairs[c].end()) it = pairs[c].insert(pairs[c].end(), key);
      pair_of[c].push_back(static_cast<std::uint16_t>(it - pairs[c].begin()));
    }
  const auto r = sweep<acc>(nn, cfg, [&](acc& s, std::uint64_t lo, std::uint64_t hi) {
    std::array<std::vector<std::uint32_t>, 3> word;
    std::vector<int> diffs(nl), visible(nl);
    for (auto j = lo; j < hi; ++j) {
      const auto& p = packed[j];
      const auto& b = normals[j];
      const std::array<int, 3> n{p.iX, p.iY, p.iZ};
      for (std::size_t c = 0; c < 3; ++c) {
        word[c].resize(pairs[c].size());
        for (std::size_t k = 0; k < pairs[c].size(); ++k) {
          const int two = t2.channel(n[c], pairs[c][k][0]) + bias, four = t4.product(pairs[c][k][1], b[c]) + bias;
          if (two < 0 || two >= 2 * bias || four < 0 || four >= 2 * bias)
            throw std::logic_error("lod.two-vs-four: a channel's dot term outside the packed word's range");
          word[c][k] = static_cast<std::uint32_t>(two) << 16 | static_cast<std::uint32_t>(four);
        }
      }
      const std::uint32_t *wx = word[0].data(), *wy = word[1].data(), *wz = word[2].data();
      const std::uint16_t *kx = pair_of[0].data(), *ky = pair_of[1].data(), *kz = pair_of[2].data();
      const int base = 3 * t2.alpha(p.alpha) - 384 - 3 * bias;
      int vmin = INT_MAX, vmax = INT_MIN, dmin = INT_MAX, dmax = INT_MIN;
      for (std::size_t i = 0; i < nl; ++i) {
        const std::uint32_t w = wx[kx[i]] + wy[ky[i]] + wz[kz[i]];
        const int two = static_cast<int>(w >> 16) + base, four = static_cast<int>(w & 0xFFFFu) - 3 * bias;
        diffs[i] = two - four;
        visible[i] = std::max(two, 0) - std::max(four, 0);
        dmin = std::min(dmin, diffs[i]), dmax = std::max(dmax, diffs[i]);
        vmin = std::min(vmin, visible[i]), vmax = std::max(vmax, visible[i]);
      }
      if (dmin < s.diff.min || dmax > s.diff.max)
        for (std::size_t i = 0; i < nl; ++i) s.diff.add(diffs[i], j * nl + i);
      if (vmin < s.visible.min || vmax > s.visible.max)
        for (std::size_t i = 0; i < nl; ++i) s.visible.add(visible[i], j * nl + i);
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
