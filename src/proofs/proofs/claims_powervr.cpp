// Seed 004: PowerVR Series 2 polar bump mapping (src/schemes/powervr). The scheme's own choices
// (precision, azimuth scale, encoder) are evaluated inside each claim, with figures per choice.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "powervr/encode.hpp"
#include "powervr/evaluate.hpp"
#include "powervr/texture.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/powervr_sweeps.hpp"

namespace gsdot3::proofs::claims {

namespace {
namespace pvr = schemes::powervr;
namespace ps = powervr_sweeps;
constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

std::string num(double v, int digits = 6) { return real_text(v, digits); }
std::string texel_text(pvr::bump_texel t) { return "S = " + hexdec(t.S) + ", R = " + hexdec(t.R); }
std::string offset_text(pvr::offset_colour k) {
  return "K1 = " + hexdec(k.K1) + ", K2 = " + hexdec(k.K2) + ", K3 = " + hexdec(k.K3) + ", Q = " + hexdec(k.Q);
}
// Angle difference wrapped to [−π, π].
double angle_diff(double a, double b) { return std::remainder(a - b, 2.0 * pi); }
}  // namespace

outcome powervr_identity(const gs::model_options&, const sweep_config& cfg) {
  // LHS in polar form (the seed's K1 + K2 sin S + K3 cos S cos(R − Q)) against the RHS as a vector dot
  // product (1 − S_l) + S_l·(N·L), N = decode_normal(texel), L from (T, Q): two different formulas.
  constexpr double tolerance = 1e-12;
  std::vector<double> Ts, Qs;
  for (int t = 0; t <= 9; ++t) Ts.push_back(t * 10.0 * deg);
  for (int q = 0; q < 8; ++q) Qs.push_back(q * 2.0 * pi / 8.0 + 0.1);
  const double Sls[] = {0.5, 1.0};
  std::vector<double> sinT, cosT;
  std::vector<glm::dvec3> Ls;
  for (double T : Ts) {
    sinT.push_back(std::sin(T)), cosT.push_back(std::cos(T));
    for (double Q : Qs) Ls.push_back({std::cos(T) * std::cos(Q), std::cos(T) * std::sin(Q), std::sin(T)});
  }
  const std::uint64_t per_texel = Ts.size() * Qs.size() * 2;
  struct acc_t {
    tally bad;
    double worst = 0;
    void merge(const acc_t& l) { bad.merge(l.bad), worst = std::max(worst, l.worst); }
  };
  const auto acc = sweep<acc_t>(65536, cfg, [&](acc_t& a, std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t i = b; i < e; ++i) {
      const auto t = pvr::bump_texel::unpack(static_cast<std::uint16_t>(i));
      const double s = pvr::elevation_of(t.S), r = pvr::azimuth_of(t.R, pvr::azimuth_scale::flycast_255);
      const glm::dvec3 N = pvr::decode_normal(t, pvr::azimuth_scale::flycast_255);
      const double sin_s = std::sin(s), cos_s = std::cos(s);
      std::uint64_t j = 0;
      for (std::size_t ti = 0; ti < Ts.size(); ++ti)
        for (std::size_t qi = 0; qi < Qs.size(); ++qi) {
          const double cos_rq = std::cos(r - Qs[qi]);
          for (double Sl : Sls) {
            const double lhs = (1 - Sl) + Sl * sinT[ti] * sin_s + Sl * cosT[ti] * cos_s * cos_rq;
            const glm::dvec3& L = Ls[ti * Qs.size() + qi];
            const double rhs = (1 - Sl) + Sl * (N.x * L.x + N.y * L.y + N.z * L.z);
            a.worst = std::max(a.worst, std::abs(lhs - rhs));
            if (std::abs(lhs - rhs) > tolerance) a.bad.add(i * per_texel + j);
            ++j;
          }
        }
    }
  });
  outcome out = verdict_of(acc.bad, 65536 * per_texel, [&](std::uint64_t i) { return "case " + std::to_string(i); });
  out.figures = {fig_real("max_abs_difference", acc.worst), fig_real("tolerance", tolerance)};
  out.note =
      "K1 = 1 − S_l, K2 = S_l sin T, K3 = S_l cos T give (1 − S_l) + S_l·N·L: cos S cos T cos(R − Q) + sin S sin T is "
      "the dot product of the two polar unit vectors (cos(a − b) = cos a cos b + sin a sin b); checked in double";
  return out;
}

outcome powervr_identity_8bit(const gs::model_options&, const sweep_config& cfg) {
  ps::identity_grid g;
  for (int q = 0; q < 256; q += 32) g.q_bytes.push_back(q);
  for (int t = 0; t <= 90; t += 15) g.elevations.push_back(t * deg);
  g.intensities = {1.0};
  outcome out;
  out.result = verdict::bound;
  out.domain_size = g.size() * pvr::all_precisions.size();
  for (const auto p : pvr::all_precisions) {
    const auto st = ps::identity_8bit_error(g, pvr::azimuth_scale::flycast_255, p, cfg);
    const std::string n = pvr::name(p);
    out.figures.push_back(fig_real(n + ".max_abs", st.max_abs));
    out.figures.push_back(fig_real(n + ".mean", st.mean()));
    out.figures.push_back(fig_real(n + ".rmse", st.rmse()));
    const auto c = ps::identity_case_at(g, pvr::azimuth_scale::flycast_255, st.arg_max);
    out.witnesses.push_back(n + " max at " + texel_text(c.texel) + ", " + offset_text(c.k) + " (T = " + num(c.T / deg) +
                            "°) => " +
                            std::to_string(pvr::intensity(c.texel, c.k, pvr::azimuth_scale::flycast_255, p)) +
                            ", exact " + num(c.expected));
  }
  out.note =
      "the 8-bit output against 255·clamp(N·L, 0, 1) (S_l = 1, K rounded to nearest, azimuths /255): K quantisation, "
      "table rounding and output rounding together, per precision option (1/255 units)";
  return out;
}

outcome powervr_q_quadrant(const gs::model_options&, const sweep_config&) {
  // Light azimuths φ = (i + 0.5)·0.1° at elevation 30°: Q as printed against the true azimuth.
  constexpr int n = 3600;
  const double T = 30.0 * deg;
  tally wrong;
  std::uint64_t wrong_atan2 = 0;
  double max_err = 0, max_err_atan2 = 0, max_intensity = 0;
  const pvr::flycast_tables fly(pvr::azimuth_scale::flycast_255);
  for (int i = 0; i < n; ++i) {
    const double phi = (i + 0.5) * 0.1 * deg;
    const glm::dvec3 P{std::cos(T) * std::cos(phi), std::cos(T) * std::sin(phi), std::sin(T)};
    const auto printed = pvr::seed_printed(P, 1.0), fixed = pvr::seed_atan2(P, 1.0);
    const double e = std::abs(angle_diff(printed.Q, phi)), e2 = std::abs(angle_diff(fixed.Q, phi));
    max_err = std::max(max_err, e), max_err_atan2 = std::max(max_err_atan2, e2);
    if (e > 1e-9) wrong.add(static_cast<std::uint64_t>(i));
    if (e2 > 1e-9) ++wrong_atan2;
    if (i % 100 == 50) {  // every 10°: the 8-bit output over every texel
      const auto kp = pvr::offset_nearest(printed, pvr::azimuth_scale::flycast_255),
                 ka = pvr::offset_nearest(fixed, pvr::azimuth_scale::flycast_255);
      for (int t = 0; t < 65536; ++t) {
        const auto tx = pvr::bump_texel::unpack(static_cast<std::uint16_t>(t));
        max_intensity = std::max(max_intensity, 255.0 * std::abs(fly.value(tx, kp) - fly.value(tx, ka)));
      }
    }
  }
  auto out = verdict_of(wrong, n, [&](std::uint64_t i) {
    const double phi = (static_cast<double>(i) + 0.5) * 0.1 * deg;
    const glm::dvec3 P{std::cos(T) * std::cos(phi), std::cos(T) * std::sin(phi), std::sin(T)};
    return "azimuth " + num(phi / deg) + "° (Px = " + num(P.x) + ", Pz = " + num(P.y) +
           ") => Q = " + num(pvr::seed_printed(P, 1).Q / deg) + "°, expected " + num(phi / deg) + "°";
  });
  out.figures = {fig("wrong_azimuths", static_cast<std::int64_t>(wrong.count)),
                 fig_real("max_azimuth_error_deg", max_err / deg),
                 fig("atan2.wrong_azimuths", static_cast<std::int64_t>(wrong_atan2)),
                 fig_real("atan2.max_azimuth_error_deg", max_err_atan2 / deg),
                 fig_real("float.max_output_difference", max_intensity)};
  out.note =
      "arctan(Pz/Px) returns (−90°, 90°): every light with Px < 0 (azimuth in (90°, 270°)) is turned by 180°, so its "
      "bump shading is inverted (max output difference over every texel, T = 30°, lights every 10°); atan2 is right "
      "everywhere";
  return out;
}

outcome powervr_azimuth_scale(const gs::model_options&, const sweep_config& cfg) {
  // (a) KallistiOS pvrtex: encoder R = azimuth·255/2π, its decoder reads R·2π/256.
  double tex_max = 0;
  int tex_arg = 0;
  for (int R = 0; R < 256; ++R) {
    const double e = std::abs(R * 360.0 / 255.0 - R * 360.0 / 256.0);
    if (e > tex_max) tex_max = e, tex_arg = R;
  }
  // (b) Q written in 1/256 turns (the SDK) and read as Q·2π/255 (flycast), K3 = 255, K1 = K2 = 0: the
  // exact intensity with the misread Q against the intended one, every (S, R, Q).
  struct acc_t {
    double max = 0;
    std::uint64_t arg = 0;
    void merge(const acc_t& l) {
      if (l.max > max) max = l.max, arg = l.arg;
    }
  };
  std::array<double, 256> cos_s{};
  for (int S = 0; S < 256; ++S) cos_s[static_cast<std::size_t>(S)] = std::cos(pvr::elevation_of(S));
  const auto acc = sweep<acc_t>(256, cfg, [&](acc_t& a, std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t Q = b; Q < e; ++Q)
      for (int R = 0; R < 256; ++R) {
        const double r = R * 2.0 * pi / 255.0;
        const double d = std::abs(std::cos(r - static_cast<double>(Q) * 2.0 * pi / 255.0) -
                                  std::cos(r - static_cast<double>(Q) * 2.0 * pi / 256.0));
        for (int S = 0; S < 256; ++S) {
          const double v = 255.0 * cos_s[static_cast<std::size_t>(S)] * d;
          if (v > a.max) a.max = v, a.arg = (Q << 16) | static_cast<std::uint64_t>(S << 8 | R);
        }
      }
  });
  outcome out;
  out.result = verdict::bound;
  out.domain_size = 256 + (1u << 24);
  out.figures = {fig_real("pvrtex.max_azimuth_error_deg", tex_max), fig("pvrtex.at_R", tex_arg),
                 fig_real("offset_q.max_output_error", acc.max),
                 fig_real("offset_q.closed_form", 255.0 * 2.0 * std::sin(pi / 256.0))};
  out.witnesses = {"pvrtex: R = " + hexdec(tex_arg) + " encoded as " + num(tex_arg * 360.0 / 255.0) + "°, decoded as " +
                       num(tex_arg * 360.0 / 256.0) + "°",
                   "offset Q: " + texel_text(pvr::bump_texel::unpack(static_cast<std::uint16_t>(acc.arg & 0xFFFF))) +
                       ", Q = " + hexdec(static_cast<std::int64_t>(acc.arg >> 16)) + " => " + num(acc.max) +
                       "/255 off"};
  out.note =
      "the azimuth error of /255 against /256 grows with the byte, R·360°/(255·256): 1.40625° at 255; in the bump unit "
      "it moves the shading by up to 255·2·sin(π/256) ≈ 6.26/255 at K3 = 255, S = 0 (exact double sweep of every (S, "
      "R, Q))";
  return out;
}

outcome powervr_sdk_arctan(const gs::model_options&, const sweep_config&) {
  // e(s) = s·(43.562812 − 11.562812·s) − (128/π)·atan(s), 1/256 turns, s ∈ [0, 1]: smooth, e(0) = 0,
  // |e''| < 60, so sampling with step h = 2^−20 misses the supremum by at most 60·h²/8 < 1e-11.
  constexpr int steps = 1 << 20;
  double max_e = 0, arg_e = 0;
  for (int i = 0; i <= steps; ++i) {
    const double s = static_cast<double>(i) / steps;
    const double e = std::abs(pvr::sdk_quadratic_arctan(s) - 128.0 / pi * std::atan(s));
    if (e > max_e) max_e = e, arg_e = s;
  }
  // The whole SDK routine (octants, rounding to the byte) over light azimuths every 0.01° at 30°
  // elevation (its frame: y = the normal, azimuth in the x-z plane).
  double max_q = 0, arg_q = 0, max_q_below = 0;
  for (int i = 0; i < 36000; ++i) {
    const double phi = i * 0.01 * deg, T = 30.0 * deg;
    const auto v =
        pvr::fxyz_light_dir_to_skk(static_cast<float>(std::cos(T) * std::cos(phi)), static_cast<float>(std::sin(T)),
                                   static_cast<float>(std::cos(T) * std::sin(phi)));
    const double e = std::abs(angle_diff(v.s * 2.0 * pi / 256.0, phi)) / deg;
    if (e > max_q) max_q = e, arg_q = phi / deg;
    if (i < 35860) max_q_below = std::max(max_q_below, e);  // below 358.6°, where 256ths round to 256
  }
  const double max_rad = max_e * 2.0 * pi / 256.0;
  outcome out;
  out.result = verdict::bound;
  out.domain_size = steps + 1 + 36000;
  out.figures = {fig_real("quadratic.max_error_256ths", max_e),
                 fig_real("quadratic.max_error_deg", max_e * 360.0 / 256.0),
                 fig_real("quadratic.at_s", arg_e),
                 fig_real("quadratic.max_output_error", 255.0 * 2.0 * std::sin(max_rad / 2.0)),
                 fig_real("routine.max_q_error_deg", max_q),
                 fig_real("routine.at_azimuth_deg", arg_q),
                 fig_real("routine.max_q_error_deg_below_358.6", max_q_below)};
  out.witnesses = {"quadratic: s = tan = " + num(arg_e, 8) + " => " + num(pvr::sdk_quadratic_arctan(arg_e), 8) +
                   ", exact " + num(128.0 / pi * std::atan(arg_e), 8) + " (1/256 turns)"};
  out.note =
      "the quadratic arctangent is within the figure shown per octant; in the bump unit (K3 = 255, S = 0) that moves "
      "the "
      "output by up to 255·2·sin(Δ/2); the routine's worst Q error is at the wrap: azimuths above 358.6° round to 256, "
      "which the SDK clamps to 255 (358.6°) instead of wrapping to 0";
  return out;
}

outcome powervr_pack_bump(const gs::model_options&, const sweep_config&) {
  // pvr_pack_bump's truncations against rounding to nearest, h = 0.1..1.0, t = 0..90° (1°), q = 0..359° (1°).
  extremes dk2, dk3, dq, dk1;
  std::uint64_t i = 0;
  for (int h10 = 1; h10 <= 10; ++h10)
    for (int td = 0; td <= 90; ++td)
      for (int qd = 0; qd < 360; ++qd, ++i) {
        const float h = static_cast<float>(h10) / 10.0f, t = static_cast<float>(td * deg),
                    q = static_cast<float>(qd * deg);
        const auto kos = pvr::pvr_pack_bump(h, t, q);
        const auto near = pvr::offset_nearest({h, t, q}, pvr::azimuth_scale::flycast_255);
        dk1.add(kos.K1 - near.K1, i), dk2.add(kos.K2 - near.K2, i), dk3.add(kos.K3 - near.K3, i);
        dq.add(((kos.Q - near.Q) % 255 + 382) % 255 - 127, i);
      }
  auto at = [](std::uint64_t j) {
    return "h = " + num(static_cast<double>(j / (91 * 360) + 1) / 10.0) + ", t = " + std::to_string(j / 360 % 91) +
           "°, q = " + std::to_string(j % 360) + "°";
  };
  outcome out;
  out.result = verdict::bound;
  out.domain_size = i;
  out.figures = {
      fig("K1.min", dk1.min), fig("K1.max", dk1.max), fig("K2.min", dk2.min),
      fig("K2.max", dk2.max), fig("K3.min", dk3.min), fig("K3.max", dk3.max),
      fig("Q.min", dq.min),   fig("Q.max", dq.max),   fig_real("Q.max_deficit_deg", -dq.min * 360.0 / 255.0)};
  out.witnesses = {"K2 min at " + at(dk2.arg_min), "K3 min at " + at(dk3.arg_min), "Q min at " + at(dq.arg_min),
                   "K1 max at " + at(dk1.arg_max)};
  out.note =
      "pvr_pack_bump truncates every byte: K2, K3 and Q come out up to one step low (Q: 1.41°), and K1 = ~(u8)(h·255) "
      "can be "
      "one step above round(255·(1 − h)) — against rounding to nearest, in bytes";
  return out;
}

outcome powervr_flipped_uv(const gs::model_options&, const sweep_config& cfg) {
  // A mirrored u makes the texture's x axis point along −t: the texel's normal, seen in the surface's
  // frame, has azimuth π − r. The hardware still evaluates cos(r − Q). Without the fix Q is the light's
  // azimuth φ; the seed's fix mirrors one local axis, so Q is encoded from π − φ. Against the exact
  // value for the mirrored normal. Lights: φ every 10°, T ∈ {30°, 60°}, S_l = 1; every texel; exact
  // double evaluation of the 8-bit K/Q (azimuths /255).
  struct acc_t {
    double nofix = 0, fix = 0;
    std::uint64_t arg = 0;
    void merge(const acc_t& l) {
      if (l.nofix > nofix) nofix = l.nofix, arg = l.arg;
      fix = std::max(fix, l.fix);
    }
  };
  constexpr auto a = pvr::azimuth_scale::flycast_255;
  struct light {
    glm::dvec3 L;
    pvr::offset_colour nofix, fix;
    std::uint64_t tag;
  };
  std::vector<light> lights;
  for (int pd = 0; pd < 360; pd += 10)
    for (int td : {30, 60}) {
      const double phi = pd * deg, T = td * deg;
      const glm::dvec3 L{std::cos(T) * std::cos(phi), std::cos(T) * std::sin(phi), std::sin(T)};
      lights.push_back({L, pvr::offset_nearest({1.0, T, phi}, a),
                        pvr::offset_nearest(pvr::seed_atan2({-L.x, L.y, L.z}, 1.0), a),
                        static_cast<std::uint64_t>(pd << 8 | td)});
    }
  const auto acc = sweep<acc_t>(65536, cfg, [&](acc_t& s, std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t i = b; i < e; ++i) {
      const auto t = pvr::bump_texel::unpack(static_cast<std::uint16_t>(i));
      glm::dvec3 N = pvr::decode_normal(t, a);
      N.x = -N.x;  // the normal in the surface's frame
      const double sn = std::sin(pvr::elevation_of(t.S)), cs = std::cos(pvr::elevation_of(t.S)),
                   r = pvr::azimuth_of(t.R, a);
      auto value = [&](pvr::offset_colour k) {
        return k.K1 + k.K2 * sn + k.K3 * cs * std::cos(r - pvr::azimuth_of(k.Q, a));
      };
      for (const auto& l : lights) {
        const double want = 255.0 * (N.x * l.L.x + N.y * l.L.y + N.z * l.L.z);
        const double e_no = std::abs(value(l.nofix) - want), e_fix = std::abs(value(l.fix) - want);
        if (e_no > s.nofix) s.nofix = e_no, s.arg = i << 16 | l.tag;
        s.fix = std::max(s.fix, e_fix);
      }
    }
  });
  // The fix leaves only the quantisation: |K_i − 255·k_i| ≤ 1/2 each (two K's: ≤ (|sin S| + |cos S|)/2 ≤ √2/2)
  // and the Q rounding, ≤ half a step π/255 of azimuth: ≤ 255·cos T·(π/255) = π·cos T ≤ π·cos 30°.
  const double bound = std::sqrt(2.0) / 2.0 + pi * std::cos(30.0 * deg);
  outcome out;
  out.result = acc.fix <= bound && acc.nofix > bound ? verdict::proven : verdict::refuted;
  out.domain_size = 65536ull * 36 * 2;
  out.figures = {fig_real("nofix.max_error", acc.nofix), fig_real("fix.max_error", acc.fix),
                 fig_real("quantisation_bound", bound)};
  const auto wt = pvr::bump_texel::unpack(static_cast<std::uint16_t>(acc.arg >> 16));
  out.witnesses = {"no fix: " + texel_text(wt) + ", light azimuth " + std::to_string(acc.arg >> 8 & 0xFF) +
                   "°, elevation " + std::to_string(acc.arg & 0xFF) + "° => " + num(acc.nofix) + "/255 off"};
  out.note =
      "mirrored UVs mirror the texel azimuth (r → π − r): without the fix the light comes from the mirrored side "
      "(error up to "
      "the nofix figure); mirroring one local axis before computing Q leaves only the 8-bit quantisation (proven "
      "within "
      "the bound). The shared mesh's triangles: tests/schemes/powervr (mesh_test)";
  return out;
}

}  // namespace gsdot3::proofs::claims
