// Section 3.6: the four-pass method — per-channel exactness, the R+G+B wrap, and the clamp/wrap audit
// of every pass of both methods.
#include <algorithm>
#include <cmath>
#include <string>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/domains.hpp"
#include "proofs/four_pass.hpp"
#include "proofs/methods.hpp"
#include "proofs/paper_code.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;

outcome four_pass_channel_exact(const gs::model_options& o, const sweep_config& cfg) {
  // Each pass writes one channel of a DPB word whose other bytes hold a marker pattern; the written
  // byte must be ((a·b) >> 7) + 128 and the other three bytes must be kept by FBMSK.
  constexpr std::uint64_t n = 3 * operands::count;
  auto bad = sweep<tally>(n, cfg, [&](tally& t, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const int channel = static_cast<int>(i / operands::count);
      const auto x = operands::at(i % operands::count);
      const std::uint32_t marker = 0x3C5AA569u, shift = 8u * static_cast<unsigned>(channel);
      const std::uint32_t dpb = (marker & ~(0xFFu << shift)) | static_cast<std::uint32_t>(x.a2) << shift;
      const std::uint32_t out = m::four_pass_channel(dpb, channel, m::byte(x.b2), o);
      const std::uint32_t want =
          (marker & ~(0xFFu << shift)) | static_cast<std::uint32_t>(char_multiply(x.a, x.b) + 128) << shift;
      if (out != want) t.add(i);
    }
  });
  auto out = verdict_of(bad, n, [&](auto i) {
    const auto x = operands::at(i % operands::count);
    return "channel " + std::to_string(i / operands::count) + ", " + x.describe() + " => " +
           hexdec(m::offset_multiply(m::byte(x.a2), m::byte(x.b2), o).value(), 12) + ", want " +
           hexdec(char_multiply(x.a, x.b) + 128);
  });
  out.note = "each pass writes exactly ((a·b) >> 7) + 128 into its channel and FBMSK keeps the other bytes";
  return out;
}

namespace {
// Section 3.6's fade_att applied by HIGHLIGHT in pass 1: vertex colour RGB = k = round(128·fade),
// A = 128 − k, fade = clamp(6·(n·l), 0, 1) with n·l = the texel direction's z (tangent-space vertex
// normal (0, 0, 1), light direction = the texel's). Returns the attenuated signed vector.
ivec3 faded(const paper::sphere_texel& t, const gs::model_options& o) {
  if (!t.inside) return {0, 0, 0};
  const float fade = std::clamp(6.0f * t.lz, 0.0f, 1.0f);
  const int k = paper::nearest(fade * 128.0f);
  const auto colour = gs::fragment_colour::flat({m::byte(k), m::byte(k), m::byte(k), m::byte(128 - k)});
  const gs::rgba8 texel{m::byte(t.r), m::byte(t.g), m::byte(t.b), m::byte(0)};
  const auto c = gs::texture_function(gs::tfx::HIGHLIGHT, gs::tcc::RGB, texel, colour, o);
  return {128 - c.r.value(), 128 - c.g.value(), 128 - c.b.value()};
}
struct sum_acc {
  tally wraps;
  extremes sum;
  void merge(const sum_acc& l) {
    wraps.merge(l.wraps);
    sum.merge(l.sum);
  }
};
sum_acc sum_sweep(const std::vector<ivec3>& lights, const std::vector<ivec3>& normals, const four_pass::table& t,
                  const sweep_config& cfg) {
  // Every pair is accounted for. normals are in (x, y, z) order with one contiguous z run per (x, y)
  // cell. For a fixed sphere vector a the z product is monotone in b_z (the table checks it: floor or
  // truncation of a_z·b/128), so over a run the sum's extremes are at the run's ends; only a run whose
  // extreme wraps or improves the running min / max is walked pair by pair (for the count and the
  // first indices). Runs are grouped in blocks of consecutive cells with the range of each
  // component: where all three products are monotone, the sum over a block lies between the sums of
  // each product's smaller and larger end value, and a block inside [−128, 127] and the running
  // extremes is skipped whole. Nothing is added inside a skipped block, so the running extremes
  // do not move there and every run in it would have been skipped: the result is the run-by-run one.
  struct cell {
    int x, y, z0;
    std::uint32_t first, count;
  };
  std::vector<cell> cells;
  for (std::uint32_t j = 0; j < normals.size(); ++j) {
    const auto& b = normals[j];
    if (!cells.empty() && cells.back().x == b[0] && cells.back().y == b[1] &&
        cells.back().z0 + static_cast<int>(cells.back().count) == b[2])
      ++cells.back().count;
    else
      cells.push_back({b[0], b[1], b[2], j, 1});
  }
  struct block {
    std::size_t begin, end;
    int x0, x1, y0, y1, z0, z1;
  };
  constexpr std::size_t block_cells = 32;
  std::vector<block> blocks;
  for (std::size_t b = 0; b < cells.size(); b += block_cells) {
    block k{b, std::min(cells.size(), b + block_cells), 128, -129, 128, -129, 128, -129};
    for (std::size_t c = k.begin; c < k.end; ++c) {
      const auto& e = cells[c];
      k.x0 = std::min(k.x0, e.x), k.x1 = std::max(k.x1, e.x), k.y0 = std::min(k.y0, e.y), k.y1 = std::max(k.y1, e.y);
      k.z0 = std::min(k.z0, e.z0), k.z1 = std::max(k.z1, e.z0 + static_cast<int>(e.count) - 1);
    }
    blocks.push_back(k);
  }
  const std::uint64_t nn = normals.size();
  return sweep<sum_acc>(lights.size(), cfg, [&](sum_acc& acc, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const auto *rx = t.row(lights[i][0]), *ry = t.row(lights[i][1]), *rz = t.row(lights[i][2]);
      const bool monotone = t.monotone(lights[i][2]);
      const bool all_monotone = monotone && t.monotone(lights[i][0]) && t.monotone(lights[i][1]);
      auto inside = [&](int lo_s, int hi_s) {
        return lo_s >= acc.sum.min && hi_s <= acc.sum.max && lo_s >= -128 && hi_s <= 127;
      };
      for (const auto& k : blocks) {
        if (all_monotone) {
          const int lo_s = std::min(rx[k.x0], rx[k.x1]) + std::min(ry[k.y0], ry[k.y1]) + std::min(rz[k.z0], rz[k.z1]);
          const int hi_s = std::max(rx[k.x0], rx[k.x1]) + std::max(ry[k.y0], ry[k.y1]) + std::max(rz[k.z0], rz[k.z1]);
          if (inside(lo_s, hi_s)) continue;
        }
        for (std::size_t ci = k.begin; ci < k.end; ++ci) {
          const cell& c = cells[ci];
          const int partial = rx[c.x] + ry[c.y];
          const std::int16_t* z = rz + c.z0;
          if (monotone) {
            const int e0 = partial + z[0], e1 = partial + z[c.count - 1];
            if (inside(std::min(e0, e1), std::max(e0, e1))) continue;
          }
          for (std::uint32_t q = 0; q < c.count; ++q) {
            const int s = partial + z[q];
            if (s < acc.sum.min || s > acc.sum.max) acc.sum.add(s, i * nn + c.first + q);
            if (s < -128 || s > 127) acc.wraps.add(i * nn + c.first + q);
          }
        }
      }
    }
  });
}
}  // namespace

outcome four_pass_sum_wrap(const gs::model_options& o, const sweep_config& cfg) {
  // Every 64×64 sphere-map texel (Appendix 1, the zero vector outside the disc) against every 8-bit
  // normal-map vector. The per-channel products come from four_pass::table (built through the
  // model; four-pass.channel-exact shows each is (a·b) >> 7), and the post filter's value is their
  // sum mod 256 (eq9.rgb-sum: exact iff the sum is in [−128, 127]).
  constexpr int size = 64;
  const auto lights = sphere_map_vectors(size);
  // Domain options: normal_map = full_sphere adds the vectors with n_z < 0; fade_att = any_vertex
  // takes the fade from a vertex whose direction is not the pixel's texel, so a vertex facing the
  // light (fade 1) can meet any texel: the faded domain contains the plain one, and is it.
  const auto normals = normal_map_vectors(cfg.domain.normals == domain_options::normal_map::full_sphere);
  const four_pass::table t(o);
  const auto plain = sum_sweep(lights, normals, t, cfg);
  std::vector<ivec3> faded_lights;
  const bool any_vertex = cfg.domain.fade == domain_options::fade_source::any_vertex;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      faded_lights.push_back(any_vertex ? lights[static_cast<std::size_t>(y * size + x)]
                                        : faded(paper::sphere_map_texel(x, y, size, size), o));
  const auto with_fade = any_vertex ? plain : sum_sweep(faded_lights, normals, t, cfg);
  const std::uint64_t nn = normals.size();
  auto describe = [&](const std::vector<ivec3>& ls, std::uint64_t i) {
    const auto& a = ls[i / nn];
    const auto& b = normals[i % nn];
    const int s = t.dot(a, b);
    auto v = [](const ivec3& u) {
      return "(" + std::to_string(u[0]) + ", " + std::to_string(u[1]) + ", " + std::to_string(u[2]) + ")";
    };
    return "texel (" + std::to_string(i / nn % size) + ", " + std::to_string(i / nn / size) + ") a = " + v(a) +
           ", b = " + v(b) + " => Σ (a·b >> 7) = " + std::to_string(s) + ", DPB dot " +
           hexdec(m::as_signed(m::byte(s)));
  };
  outcome out;
  out.result = plain.wraps.count == 0 ? verdict::proven : verdict::refuted;
  out.domain_size = lights.size() * nn;
  out.counterexamples = plain.wraps.count;
  for (auto i : plain.wraps.first) out.witnesses.push_back(describe(lights, i));
  if (plain.wraps.count == 0) {
    out.witnesses.push_back("sum_min at " + describe(lights, plain.sum.arg_min));
    out.witnesses.push_back("sum_max at " + describe(lights, plain.sum.arg_max));
  }
  for (auto i : with_fade.wraps.first) out.witnesses.push_back("with fade_att: " + describe(faded_lights, i));
  out.figures = {fig("normal_map_vectors", static_cast<std::int64_t>(nn)),
                 fig("sum_min", plain.sum.min),
                 fig("sum_max", plain.sum.max),
                 fig("count", static_cast<std::int64_t>(plain.wraps.count)),
                 fig("fade_sum_min", with_fade.sum.min),
                 fig("fade_sum_max", with_fade.sum.max),
                 fig("fade_count", static_cast<std::int64_t>(with_fade.wraps.count))};
  out.note = plain.wraps.count == 0
                 ? "the summed products stay in [−128, 127]: R+G+B never wraps"
                 : "the summed products reach " + std::to_string(plain.sum.min) +
                       " < −128 for near-opposite vectors (three floors): those pixels wrap to a bright positive dot; "
                       "fade_att leaves " +
                       std::to_string(with_fade.wraps.count) + " of them";
  return out;
}

outcome clamp_wrap_intermediates(const gs::model_options& o, const sweep_config& cfg) {
  // Each pass, every intermediate over its whole input range:
  //  (1) two-pass MODULATE (passes 1 and 2): palette value 0..128 × Gouraud light 0..0x7FFF (8.7):
  //      the TFX clamp to 255 must never bite;
  //  (2) two-pass pass 2 alpha: n'_a 0..255 × vertex alpha 0x80: no clamp;
  //  (3) two-pass pass 2 blend Cd − Cs over the same range, for n in [−127, 128] (one side is 0): the
  //      wrapped byte must be ≡ the value (mod 256), negatives wrap (wanted);
  //  (4) four-pass pass 1 HIGHLIGHT attenuation: texel 0..255 × k 0..128: no clamp;
  //  (5) four-pass passes 2-4 blend: eq. (8) output in 0..255 for every (a2, b2): neither clamp nor wrap.
  // The post filters' sums are mod 256 by design (eq9.rgb-sum).
  struct acc {
    std::uint64_t tfx_clamps = 0, wraps_wanted = 0, wrong_wrap = 0;
    tally bad;
    void merge(const acc& l) {
      tfx_clamps += l.tfx_clamps, wraps_wanted += l.wraps_wanted, wrong_wrap += l.wrong_wrap;
      bad.merge(l.bad);
    }
  };
  constexpr std::uint64_t lights = 1u << 15, n1 = 256 * lights;  // n index 0..255 ↔ n = index − 127
  auto r = sweep<acc>(n1, cfg, [&](acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const int n = static_cast<int>(i / lights) - 127, pos = std::max(n, 0), neg = std::max(-n, 0);
      const auto L = gs::gouraud_channel::from_wrapped(static_cast<int>(i % lights));
      const gs::fragment_colour light{L, L, L, gs::gouraud_channel::from_wrapped(0x80 << 7)};
      const bool clamp1 = gs::modulate_channel(m::byte(pos), L, o).value() > 255;
      const bool clamp2 = gs::modulate_channel(m::byte(neg), L, o).value() > 255;
      const auto dpb = m::two_pass_pass1(m::grey(pos, 0), light, o);
      const auto p2 = m::two_pass_pass2_wide(m::grey(neg, 0), light, dpb, o);
      const int v = p2.wide.r.value(), b = gs::colclamp_channel(p2.wide.r, false).value();
      if (clamp1 || clamp2) ++s.tfx_clamps;
      if (v < 0) ++s.wraps_wanted;
      if (((b - v) & 0xFF) != 0) ++s.wrong_wrap;
      if (clamp1 || clamp2 || ((b - v) & 0xFF) != 0) s.bad.add(i);
    }
  });
  std::int64_t alpha_clamps = 0, highlight_clamps = 0, blend_outside = 0;
  for (int a = 0; a < 256; ++a)
    if (gs::modulate_channel(m::byte(a), gs::gouraud_channel::from_wrapped(0x80 << 7), o).value() > 255) ++alpha_clamps;
  for (int t = 0; t < 256; ++t)
    for (int k = 0; k <= 128; ++k)
      if (gs::modulate_channel(m::byte(t), gs::gouraud_channel::from_wrapped(k << 7), o).value() + (128 - k) > 255)
        ++highlight_clamps;
  for (std::uint64_t i = 0; i < operands::count; ++i) {
    const auto x = operands::at(i);
    const int v = m::offset_multiply(m::byte(x.a2), m::byte(x.b2), o).value();
    if (v < 0 || v > 255) ++blend_outside;
  }
  const std::uint64_t size = n1 + 256 + 256 * 129 + operands::count;
  if (alpha_clamps + highlight_clamps + blend_outside > 0) r.bad.add(n1);
  auto out = verdict_of(r.bad, size, [&](auto i) {
    if (i >= n1) return std::string("alpha / HIGHLIGHT clamp or four-pass blend outside 0..255");
    return "n = " + std::to_string(static_cast<int>(i / lights) - 127) + ", light 8.7 " +
           hexdec(static_cast<std::int64_t>(i % lights), 16);
  });
  out.figures = {fig("tfx_clamp_bites", static_cast<std::int64_t>(r.tfx_clamps) + alpha_clamps + highlight_clamps),
                 fig("two_pass_wraps_wanted", static_cast<std::int64_t>(r.wraps_wanted)),
                 fig("two_pass_wrong_wraps", static_cast<std::int64_t>(r.wrong_wrap)),
                 fig("four_pass_blend_outside_byte", blend_outside)};
  out.note =
      "the texture function's clamp never bites; the two-pass subtraction wraps exactly mod 256 (for "
      "the negative products, as intended); the four-pass blend stays in 0..255";
  return out;
}

}  // namespace gsdot3::proofs::claims
