// proofs_triangle boxes — certificates of two-pass.max-s.interpolated under gouraud_setup=per_pixel
// with gouraud_fraction=truncate_to_8 (the dobiestation profile). Not a benchmark and not a test: a
// reproducible tool (no randomness); every row it prints is re-verified by the claim and replayed
// through the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle boxes S [SHARD COUNT]   (always gouraud_fraction=truncate_to_8)
// Under per_pixel the pixel's light is the exact plane (within one 8.7 unit) and truncate_to_8 hands the
// multiply its integer level m = floor: a pixel wraps when the unit box [m, m + 1)³ of a wrapping
// integer vector m meets a triangle of three packed lights. For each Appendix 2 normal the bound
// leaves open at S (two_pass::triangle::cannot_wrap with the light set) and each wrap side: the
// integer m within 2 levels of a packed light of the cap (the lights at most 4·|n| below the best
// along the normal) whose flat value wraps, then every triple of cap lights within 3 levels of m's
// box centre, the triangle clipped to the box shrunk by 0.03 level (the exact plane's truncation moves
// a light by under 1/128), its centroid P placed as the pixel (2047·β, 2047·γ) of the screen triangle
// (0, 0), (2047, 0), (0, 2047), and the pixel scored exactly (pixel_light under per_pixel, then
// two_pass::pixel). Prints the first wrapping case per normal, at most three, as certificate rows.
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

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
using point = std::array<double, 3>;

double dot(const point& a, const point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
point to_point(const p::ivec3& l) { return {double(l[0]), double(l[1]), double(l[2])}; }

// The part of a convex polygon with x_k <= bound (sign +1) or x_k >= bound (sign −1).
std::vector<point> clip(const std::vector<point>& poly, int k, int sign, double bound) {
  std::vector<point> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point& a = poly[i];
    const point& b = poly[(i + 1) % poly.size()];
    const double fa = sign * (a[k] - bound), fb = sign * (b[k] - bound);
    if (fa <= 0) out.push_back(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const double t = fa / (fa - fb);
      out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
    }
  }
  return out;
}

// The pixel of the screen triangle whose exact plane is nearest the box's part of triangle (a, b, c),
// or px = −1 when the triangle misses the shrunk box.
tt::triangle_case place(int s, const p::paper::packed_normal& nm, const std::array<p::ivec3, 3>& l, const p::ivec3& m) {
  constexpr double inset = 0.03;
  std::vector<point> poly{to_point(l[0]), to_point(l[1]), to_point(l[2])};
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    poly = clip(poly, k, 1, m[static_cast<std::size_t>(k)] + 1 - inset);
    if (!poly.empty()) poly = clip(poly, k, -1, m[static_cast<std::size_t>(k)] + inset);
  }
  tt::triangle_case k{s, nm.iX, nm.iY, l, {0, 0, 32752, 0, 0, 32752}, -1, -1};
  if (poly.empty()) return k;
  point P{0, 0, 0};
  for (const auto& q : poly)
    for (std::size_t c = 0; c < 3; ++c) P[c] += q[c] / static_cast<double>(poly.size());
  const point A = to_point(l[0]), u{l[1][0] - A[0], l[1][1] - A[1], l[1][2] - A[2]},
              v{l[2][0] - A[0], l[2][1] - A[1], l[2][2] - A[2]}, w{P[0] - A[0], P[1] - A[1], P[2] - A[2]};
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), den = uu * vv - uv * uv;
  if (std::fabs(den) < 1e-9) return k;  // collinear lights
  const double beta = (dot(w, u) * vv - dot(w, v) * uv) / den, gamma = (dot(w, v) * uu - dot(w, u) * uv) / den;
  const int px = static_cast<int>(std::lround(2047 * beta)), py = static_cast<int>(std::lround(2047 * gamma));
  if (px >= 0 && py >= 0 && px + py <= 2047) k.px = px, k.py = py;
  return k;
}

struct boxes_args {
  gsdot3::tools::search_args search{0, true, gs::gouraud_setup::per_pixel};
  int shard = 0, count = 1;
};

int run(const boxes_args& a) {
  const int shard = a.shard, count = a.count;
  const int s = a.search.s;
  const gs::model_options o = a.search.options();
  const p::two_pass::table t(o);
  const auto lights = p::packed_lights(s);
  const auto& normals = p::appendix2_normals();
  gsdot3::tools::progress progress("boxes: Appendix 2 normals", static_cast<long long>(normals.size()));
  int index = 0, open = 0, found = 0;
  for (const auto& nm : normals) {
    progress.at(index);
    if (index++ % count != shard) continue;
    const int e = t.alpha_error(nm);
    if (tt::cannot_wrap(nm, e, s, o, lights)) continue;
    ++open;
    const int n[3] = {nm.iX, nm.iY, nm.iZ};
    const double len = std::sqrt(double(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
    bool wrapped = false;
    for (int side : {1, -1}) {
      auto along = [&](const p::ivec3& l) { return side * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]); };
      auto wraps = [&](int v) { return side > 0 ? v >= 128 : v <= -129; };
      int best = -(1 << 30);
      for (const auto& l : lights) best = std::max(best, along(l));
      std::vector<p::ivec3> cap, boxes;
      for (const auto& l : lights)
        if (along(l) >= best - 4 * len) cap.push_back(l);
      for (const auto& l : cap)
        for (int dx = -2; dx <= 2; ++dx)
          for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz) {
              const p::ivec3 m{l[0] + dx, l[1] + dy, l[2] + dz};
              if (std::abs(m[0]) > 127 || std::abs(m[1]) > 127 || std::abs(m[2]) > 127 || along(m) < best - 2 * len)
                continue;
              if (std::find(boxes.begin(), boxes.end(), m) != boxes.end()) continue;
              if (wraps(p::two_pass::pixel(nm, gs::fragment_colour::flat(tt::light_colour(m)), o).value))
                boxes.push_back(m);
            }
      for (const auto& m : boxes) {
        std::vector<p::ivec3> near;
        for (const auto& l : cap) {
          double d = 0;
          for (std::size_t c = 0; c < 3; ++c) d += (l[c] - (m[c] + 0.5)) * (l[c] - (m[c] + 0.5));
          if (d <= 9) near.push_back(l);
        }
        for (std::size_t a = 0; a < near.size() && !wrapped; ++a)
          for (std::size_t b = a + 1; b < near.size() && !wrapped; ++b)
            for (std::size_t c = b + 1; c < near.size() && !wrapped; ++c) {
              const tt::triangle_case k = place(s, nm, {near[a], near[b], near[c]}, m);
              if (k.px < 0) continue;
              const auto r = p::two_pass::pixel(nm, tt::pixel_light(k, o.setup), o);
              if (r.dot == r.value) continue;
              wrapped = true;
              std::printf(
                  "    {%d, %d, %d, {{{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}}}, {0, 0, 32752, 0, 0, 32752}, %d, %d}, "
                  " "
                  "// value %d, side %d, box m = (%d, %d, %d)\n",
                  s, nm.iX, nm.iY, k.light[0][0], k.light[0][1], k.light[0][2], k.light[1][0], k.light[1][1],
                  k.light[1][2], k.light[2][0], k.light[2][1], k.light[2][2], k.px, k.py, r.value, side, m[0], m[1],
                  m[2]);
              std::fflush(stdout);
            }
        if (wrapped) break;
      }
      if (wrapped) break;
    }
    if (wrapped && ++found >= 3) break;
  }
  std::printf("s = %d: %d normals of this shard open by the bound, %d with a wrap printed\n", s, open, found);
  return 0;
}
}  // namespace

void gsdot3::tools::add_boxes_command(CLI::App& app, int& rc) {
  auto a = std::make_shared<boxes_args>();
  CLI::App* cmd = app.add_subcommand("boxes",
                                     "Unit boxes of wrapping integer lights under per_pixel with truncate_to_8: the "
                                     "certificate row at s = 124 (per_pixel)");
  cmd->footer(
      "Prints up to three certificate rows, one per normal, and how many normals the bound leaves open. `124`: ~4 "
      "min.");
  cmd->add_option("S", a->search.s, "The light scale s: the vertex lights are packed lights of L_s")
      ->required()
      ->check(CLI::Range(1, 127));
  cmd->add_option("SHARD", a->shard, "Run the normals with index = SHARD mod COUNT only (default 0)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("COUNT", a->count, "(default 1)")->check(CLI::PositiveNumber);
  cmd->callback([a, &rc] {
    if (a->shard >= a->count) throw CLI::ValidationError("SHARD", "must be below COUNT");
    rc = run(*a);
  });
}
