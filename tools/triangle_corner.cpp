// proofs_triangle corner — triangle certificates of two-pass.max-s.interpolated from the corner
// model. Not a benchmark and not a test: a reproducible tool (no randomness); every row it prints is
// re-verified by the claim and replayed through the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle corner S [--truncate-to-8] [CANDIDATES]
// The corner model (case (ii) of the bound in src/proofs/two_pass_triangle/two_pass_triangle/two_pass_triangle.hpp at
// its extreme): X = (0, yX), Y = (xY, 0), Z = (xZ, yZ) near the window's corners, so the reference pixel is r = (0, 0)
// and the pixel p next to Z lies ~2046 pixels from it along both axes. X and Y carry the light u, Z the light v. On two
// channels (the lag channels) u = v + 16·σ_c (σ_c the wrap side's sign): with Z and X's y, Y's x moved by sub-pixel
// amounts both steps are just below one unit per pixel and truncate to 0, so the pixel keeps the plane's value at r, u
// + ~15.98 levels (~2046 units: both axes' lag, 32 levels above v). The third channel keeps v less what its steps'
// truncation loses (its difference u − v is free, u on the shell next to the lag channels; with both
// lag steps just below 1 it loses most of a level on one axis, see two_pass_triangle.hpp).
//   1. Candidates: for every Appendix 2 normal the bound does not settle at S, both wrap sides and
//      each choice of the third channel, every packed light v of L_S with u (lag channels v + 16·σ,
//      third channel any value that puts u on the shell) a packed light too; ranked by the model's
//      value for that light (lag channels v + 16·σ + 2046/128 levels, third channel v − ½ level,
//      truncate_to_8's floor applied) plus the floors' most favourable rounding (+1 per channel that
//      can gain); under truncate_to_8 the rank is exact for the structure: the pixel's light is then a
//      whole level per channel, so two_pass::table gives its value (lag channels 32 levels past v
//      on the side the floor rounds to, 31 on the other; the third channel v, or v − 1 where the
//      floor loses). The best CANDIDATES (default 300) are kept, best first.
//   2. Geometry: for each candidate and each pair of third-channel values at X and Y, Z = (2047 −
//      α, 2047 − β) with α, β in {0, 4, 8, 16, 32}/16 pixel, X's y = yZ − t with t = 1/16 .. 2 pixels
//      (1/16 apart) and 3 .. 160 pixels (1 apart), and Y's x = xZ − t' for the first 8 12.4 values of
//      t' for which the lag channels' exact x and y gradients are both below one unit per pixel
//      (2048·(yZ − t) < det and 2048·(xZ − t') < det, det = xZ·yZ − t·t', in pixels). Each case is
//      scored exactly (score_near_vertices: the covered pixels within 1 of Z through tt::pixel_light
//      and two_pass::pixel).
//   3. Local search: from each candidate's best geometry, a steepest ascent over the six 12.4
//      coordinates (±1, ±2, ±4, ±8, ±16, ±64, ±256) and the three lights (±1 per channel, kept
//      packed), on the wrap-side value plus its smooth part.
// Prints the first wrapping case as a certificate row, or the best wrap-side value reached.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "triangle_args.hpp"
#include "triangle_score.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;
using gsdot3::tools::scored;

namespace {
constexpr int E = (tt::window_pixels - 1) * 16;  // 2047.0 in 12.4

struct candidate {
  double rank;  // the model's wrap-side value with the floors' best rounding
  int iX, iY, side;
  p::ivec3 v, u;                // u's third channel is a placeholder
  int third;                    // the channel that does not lag
  std::vector<int> third_at_u;  // the values of u's third channel that put u on the shell
};

double total(const scored& x) { return x.value + x.smooth; }

// The model's light (8.7) for one channel, with truncate_to_8's floor.
double model_units(double units, const gs::model_options& o) {
  return o.gouraud == gs::gouraud_fraction::truncate_to_8 ? 128.0 * std::floor(units / 128.0) : units;
}

std::vector<candidate> corner_candidates(int s, const gs::model_options& o, const p::two_pass::table& t,
                                         std::size_t keep) {
  const auto lights = p::packed_lights(s);
  // the best `keep` so far, worst first (a heap on rank); the prefilter rises with it
  std::vector<candidate> out;
  auto worse = [](const candidate& a, const candidate& b) { return a.rank > b.rank; };
  auto floor_rank = [&] { return out.size() < keep ? 127.5 : out.front().rank; };
  // (normal, side, third channel) in decreasing order of a bound on their rank (v = s·n̂ along the
  // wrap side): once the heap's worst beats the bound, no later one can enter.
  struct group {
    double bound;
    const p::paper::packed_normal* nm;
    int side, k;
  };
  std::vector<group> groups;
  for (const auto& nm : p::appendix2_normals()) {
    const int e = t.alpha_error(nm);
    if (tt::cannot_wrap(nm, e, s, o)) continue;
    const int n[3] = {nm.iX, nm.iY, nm.iZ};
    const int neg = (n[0] < 0) + (n[1] < 0) + (n[2] < 0), l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
    const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
    for (int side : {1, -1})
      for (int k = 0; k < 3; ++k)
        groups.push_back({(side > 0 ? e : -e - 1) + (side > 0 ? neg : 3 - neg) +
                              (len * s + 32.0 * (l1 - std::abs(n[k])) +
                               (o.gouraud == gs::gouraud_fraction::truncate_to_8 ? l1 : 0)) /
                                  128.0,
                          &nm, side, k});
  }
  std::stable_sort(groups.begin(), groups.end(), [](const group& a, const group& b) { return a.bound > b.bound; });
  for (const auto& g : groups) {
    if (g.bound <= floor_rank()) break;
    const auto& nm = *g.nm;
    const int e = t.alpha_error(nm), side = g.side, k = g.k;
    const int n[3] = {nm.iX, nm.iY, nm.iZ};
    const int neg = (n[0] < 0) + (n[1] < 0) + (n[2] < 0);
    {
      int sigma[3];
      for (int c = 0; c < 3; ++c) sigma[c] = side * (n[c] >= 0 ? 1 : -1);
      const int slack = side > 0 ? neg : 3 - neg;
      {
        // prefilter: the rank below is at most e·side + (n_σ·v + lag + |n|_1·(truncate_to_8's level))/128 + slack
        int lag = 0, l1 = 0;
        for (int c = 0; c < 3; ++c) lag += c != k ? std::abs(n[c]) * 32 : 0, l1 += std::abs(n[c]);
        const double need = 128.0 * (floor_rank() - slack - (side > 0 ? e : -e - 1)) - lag -
                            (o.gouraud == gs::gouraud_fraction::truncate_to_8 ? l1 : 0);
        for (const auto& v : lights) {
          if (std::abs(n[0]) * sigma[0] * v[0] + std::abs(n[1]) * sigma[1] * v[1] + std::abs(n[2]) * sigma[2] * v[2] <
              need)
            continue;
          p::ivec3 u = v;
          double real = e;
          int r2 = s * s;
          bool fits = true;
          for (int c = 0; c < 3; ++c) {
            const auto cc = static_cast<std::size_t>(c);
            double units = 128.0 * (128 + v[cc]);
            if (c != k) {
              u[cc] = v[cc] + 16 * sigma[c];
              fits = fits && std::abs(u[cc]) <= s;
              r2 -= u[cc] * u[cc];
              units += sigma[c] * (2048.0 + 2046.0);
            } else {
              units -= sigma[c] * 64.0;
            }
            real += n[c] * (model_units(units, o) - 16384) / 16384.0;
          }
          double rank = (side > 0 ? real : -real - 1) + slack;
          if (o.gouraud == gs::gouraud_fraction::truncate_to_8) {
            // the pixel's light is then a whole level per channel, so the model's value is the flat
            // light's (two_pass::table): lag channels 32 levels past v on the side truncation rounds
            // to (31 on the other), the third channel v (one level less where truncation loses)
            p::ivec3 l = v;
            for (int c = 0; c < 3; ++c) {
              auto& x = l[static_cast<std::size_t>(c)];
              x = c != k ? x + (sigma[c] > 0 ? 31 : -32) : x - (sigma[c] > 0 ? 1 : 0);
              x = std::clamp(x, -128, 127);
            }
            const int value = t.value(nm, l);
            rank =
                (side > 0 ? value : -value - 1) + (rank - slack - std::floor(rank - slack));  // ties: the smooth part
          }
          if (!fits || r2 < 0 || rank <= floor_rank()) continue;
          candidate cand{rank, nm.iX, nm.iY, side, v, u, k, {}};
          const int w0 = static_cast<int>(std::sqrt(static_cast<double>(r2)));
          for (int w = -w0 - 1; w <= w0 + 1; ++w) {
            if (std::abs(w) < w0 - 1) continue;
            p::ivec3 x = u;
            x[static_cast<std::size_t>(k)] = w;
            if (p::is_packed_light(s, x)) cand.third_at_u.push_back(w);
          }
          if (cand.third_at_u.empty()) continue;
          if (out.size() == keep) std::pop_heap(out.begin(), out.end(), worse), out.pop_back();
          out.push_back(std::move(cand)), std::push_heap(out.begin(), out.end(), worse);
        }
      }
    }
  }
  std::sort_heap(out.begin(), out.end(), worse);  // best first
  return out;
}

// Step 2: the geometries whose lag channels' steps both truncate to 0, scored exactly.
std::pair<tt::triangle_case, scored> best_geometry(tt::triangle_case c, const gs::model_options& o,
                                                   const p::two_pass::table& t, int side, long& evaluated) {
  tt::triangle_case best_c = c;
  scored best;
  for (int a16 : {0, 4, 8, 16, 32})
    for (int b16 : {0, 4, 8, 16, 32}) {
      const int xz = E - a16, yz = E - b16;
      const double xZ = xz / 16.0, yZ = yz / 16.0;
      for (int t16 = 1; t16 <= 16 * 160; t16 += t16 < 32 ? 1 : 16) {
        const double tp = t16 / 16.0;
        const double lo = xZ * (2048 - yZ) / (2048 - tp), hi = (xZ * yZ - 2048 * (yZ - tp)) / tp;
        const int first = static_cast<int>(std::floor(16 * lo)) + 1,
                  last = std::min(static_cast<int>(std::ceil(16 * hi)) - 1, first + 7);
        for (int s16 = first; s16 <= last; ++s16) {
          c.xy16 = {0, yz - t16, xz - s16, 0, xz, yz};
          const scored sc = gsdot3::tools::score_near_vertices(c, o, t, side, 1, 4);
          ++evaluated;
          if (total(sc) > total(best)) best = sc, best_c = c;
        }
      }
    }
  return {best_c, best};
}

// Step 3: steepest ascent over the coordinates and the lights.
std::pair<tt::triangle_case, scored> climb(tt::triangle_case c, scored cur, const gs::model_options& o,
                                           const p::two_pass::table& t, int side, long& evaluated) {
  for (int round = 0; round < 200; ++round) {
    tt::triangle_case best_c = c;
    scored best = cur;
    auto consider = [&](const tt::triangle_case& q) {
      const scored sc = gsdot3::tools::score_near_vertices(q, o, t, side, 1, 4);
      ++evaluated;
      if (total(sc) > total(best)) best = sc, best_c = q;
    };
    for (std::size_t i = 0; i < 6; ++i)
      for (int d : {1, 2, 4, 8, 16, 64, 256})
        for (int sgn : {1, -1}) {
          tt::triangle_case q = c;
          q.xy16[i] = std::clamp(q.xy16[i] + sgn * d, 0, E);
          if (q.xy16 != c.xy16) consider(q);
        }
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t ch = 0; ch < 3; ++ch)
        for (int sgn : {1, -1}) {
          tt::triangle_case q = c;
          q.light[k][ch] += sgn;
          if (p::is_packed_light(c.s, q.light[k])) consider(q);
        }
    if (total(best) <= total(cur)) break;
    c = best_c, cur = best;
  }
  return {c, cur};
}

struct corner_args {
  gsdot3::tools::search_args search;
  long keep = 300;
};

int run(const corner_args& a) {
  const auto& args = a.search;
  const int s = args.s;
  const gs::model_options o = args.options();
  const long keep = a.keep;
  const p::two_pass::table t(o);
  const auto cands = corner_candidates(s, o, t, static_cast<std::size_t>(keep));
  std::fprintf(stderr, "s = %d (%s): %zu corner candidates\n", s, args.option_name(), cands.size());
  long evaluated = 0;
  scored overall;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const candidate& k = cands[i];
    for (int wx : k.third_at_u)
      for (int wy : k.third_at_u) {
        p::ivec3 lx = k.u, ly = k.u;
        lx[static_cast<std::size_t>(k.third)] = wx, ly[static_cast<std::size_t>(k.third)] = wy;
        const tt::triangle_case c{s, k.iX, k.iY, {lx, ly, k.v}, {}, 0, 0};
        auto [gc, gs_] = best_geometry(c, o, t, k.side, evaluated);
        auto [fc, fs] = climb(gc, gs_, o, t, k.side, evaluated);
        if (total(fs) > total(overall)) overall = fs;
        std::fprintf(
            stderr,
            "candidate %zu (rank %.3f, n = (%d, %d), side %+d): geometry %d (%.3f), climbed %d (%.3f); %ld evaluated\n",
            i, k.rank, k.iX, k.iY, k.side, gs_.value, gs_.smooth, fs.value, fs.smooth, evaluated);
        if (fs.value >= 128) {
          gsdot3::tools::print_certificate_row(fc, fs, args.option_name());
          return 0;
        }
      }
  }
  std::printf(
      "s = %d (%s): no wrap found (%zu candidates, %ld cases evaluated, best wrap-side value %d, smooth %.3f)\n", s,
      args.option_name(), cands.size(), evaluated, overall.value, overall.smooth);
  return 1;
}
}  // namespace

void gsdot3::tools::add_corner_command(CLI::App& app, int& rc) {
  auto a = std::make_shared<corner_args>();
  CLI::App* cmd = app.add_subcommand("corner", "The corner model: the certificate rows at s = 89 (one per option)");
  cmd->footer(
      "Prints the first wrapping case as a certificate row (exit status 0), or the best value reached (1); "
      "a line per candidate on stderr. Minutes.");
  add_search_args(*cmd, a->search);
  cmd->add_option("CANDIDATES", a->keep, "How many of the best-ranked lattice candidates to try (default 300)")
      ->check(CLI::PositiveNumber);
  cmd->callback([a, &rc] { rc = run(*a); });
}
