// proofs_triangle_anneal — a guided local search for triangle certificates of
// two-pass.max-s.interpolated below the construction of proofs_triangle_search (s = 100). Not a
// benchmark and not a test: a reproducible tool (fixed seeds); every row it prints is re-verified by
// the claim and replayed through the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle_anneal S [truncate_to_8] [SEED] [STEPS]
// State: an Appendix 2 normal, three packed lights of L_S, three vertices in 12.4. Score: the
// largest |wrap side| value over the covered pixels within 2 pixels of each vertex (the GS's light
// plane is linear, so the extreme pixel lies next to a vertex), with the exact Σ n_c·L_c as the
// smooth part. Starts: the s = 100 certificate's geometry (one axis of lag), its mirror, and the
// two-axis right triangle (0, H), (W, 0), (W, H) whose far vertex lags along both axes; lights from
// the certificate scaled to S. Moves: a vertex by up to ±64/16 pixel (sometimes ±1024/16), a light
// by ±2 per channel kept on the shell, the normal by ±2. Simulated annealing, geometric cooling.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <utility>

#include "proofs_search_args.hpp"
#include "proofs_triangle_score.hpp"
#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "proofs/two_pass_triangle.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
using gsdot3::bench::scored;
constexpr int max124 = (tt::window_pixels - 1) * 16;

scored evaluate(const tt::triangle_case& c, const gs::model_options& o, const p::two_pass::table& t, int side) {
  return gsdot3::bench::score_near_vertices(c, o, t, side);
}
}  // namespace

int main(int argc, char** argv) {
  const auto args = gsdot3::bench::parse_search_args(argc, argv, "proofs_triangle_anneal", " [SEED] [STEPS]");
  const int s = args.s;
  const gs::model_options o = args.o;
  const unsigned seed = argc > args.next ? static_cast<unsigned>(std::atoi(argv[args.next])) : 1u;
  const long steps = argc > args.next + 1 ? std::atol(argv[args.next + 1]) : 200000;
  const p::two_pass::table t(o);
  std::set<std::pair<int, int>> normal_set;
  for (const auto& nm : p::appendix2_normals()) normal_set.insert({nm.iX, nm.iY});
  const auto lights = p::packed_lights(s);
  std::mt19937_64 rng(seed);
  auto nearest_light = [&](double x, double y, double z) {
    p::ivec3 best = lights[0];
    double bd = 1e18;
    for (const auto& l : lights) {
      const double d = (l[0] - x) * (l[0] - x) + (l[1] - y) * (l[1] - y) + (l[2] - z) * (l[2] - z);
      if (d < bd) bd = d, best = l;
    }
    return best;
  };
  // the s = 100 row of proofs_triangle_search's construction (the first row with s = 100)
  const tt::triangle_case seedc = *std::find_if(tt::certificates().begin(), tt::certificates().end(), [](const tt::triangle_case& k) { return k.s == 100; });
  long total = 0;
  for (int start = 0;; ++start) {
    tt::triangle_case c = seedc;
    c.s = s;
    const bool mirror = (start & 1) != 0;  // the lights negated: the other wrap side
    for (std::size_t k = 0; k < 3; ++k) {
      const double f = static_cast<double>(s) / seedc.s;
      c.light[k] = nearest_light(seedc.light[k][0] * f, seedc.light[k][1] * f, seedc.light[k][2] * f);
    }
    if (mirror)
      for (auto& l : c.light) l = {-l[0], -l[1], std::clamp(-l[2], -s, s)}, l = nearest_light(l[0], l[1], l[2]);
    if ((start >> 1) % 3 == 1) {  // two-axis: the first certificate of that shape, its lights scaled to S
      const auto& two = *std::find_if(tt::certificates().begin(), tt::certificates().end(), [](const tt::triangle_case& k) {
        return k.xy16 == std::array<int, 6>{0, max124, max124, 0, max124, max124};
      });
      c = two, c.s = s;
      for (std::size_t k = 0; k < 3; ++k) {
        const double f = static_cast<double>(s) / two.s;
        c.light[k] = nearest_light(two.light[k][0] * f, two.light[k][1] * f, two.light[k][2] * f);
      }
    }
    if ((start >> 1) % 3 == 2) c.xy16 = {max124 - seedc.xy16[0], 0, max124, max124, max124 - seedc.xy16[4], max124};
    std::uniform_int_distribution<int> pick(0, 99);
    const int side = evaluate(c, o, t, 1).smooth >= evaluate(c, o, t, -1).smooth ? 1 : -1;
    scored cur = evaluate(c, o, t, side), best = cur;
    tt::triangle_case best_c = c;
    double temp = 2.0;
    const double cool = std::pow(0.002 / temp, 1.0 / static_cast<double>(steps));
    for (long i = 0; i < steps; ++i, temp *= cool) {
      tt::triangle_case nxt = c;
      const int m = pick(rng);
      if (m < 45) {
        const int k = static_cast<int>(rng() % 6);
        const int span = pick(rng) < 10 ? 1024 : 64;
        nxt.xy16[static_cast<std::size_t>(k)] = std::clamp(nxt.xy16[static_cast<std::size_t>(k)] + static_cast<int>(rng() % (2 * span + 1)) - span, 0, max124);
      } else if (m < 90) {
        auto& l = nxt.light[rng() % 3];
        p::ivec3 v = l;
        for (auto& x : v) x += static_cast<int>(rng() % 5) - 2;
        if (!p::is_packed_light(s, v)) continue;
        l = v;
      } else {
        const int ix = nxt.iX + static_cast<int>(rng() % 5) - 2, iy = nxt.iY + static_cast<int>(rng() % 5) - 2;
        if (!normal_set.count({ix, iy})) continue;
        nxt.iX = ix, nxt.iY = iy;
      }
      const scored sc = evaluate(nxt, o, t, side);
      ++total;
      const double delta = (sc.smooth + sc.value) - (cur.smooth + cur.value);
      if (delta >= 0 || std::uniform_real_distribution<double>(0, 1)(rng) < std::exp(delta / temp)) {
        c = nxt, cur = sc;
        if (cur.smooth + cur.value > best.smooth + best.value) best = cur, best_c = c;
      }
    }
    std::fprintf(stderr, "start %d (side %+d): best value %d (smooth %.3f), %ld evaluated\n", start, side, best.value, best.smooth, total);
    if (best.value >= 128) {
      gsdot3::bench::print_certificate_row(best_c, best, args.option_name());
      return 0;
    }
    if (start >= 5) break;
  }
  std::printf("s = %d: no wrap found (%ld evaluated)\n", s, total);
  return 1;
}
