// triangle_score.hpp — the exact score the certificate searches of tools/proofs_triangle share: a case's
// covered pixels next to its vertices, each light through tt::pixel_light and the pixel through the
// model's two-pass passes (two_pass::pixel), and the certificate row in the table's format
// (src/proofs/two_pass_triangle/certificates.csv).
#pragma once

#include <cstddef>
#include <cstdio>
#include <set>
#include <utility>

#include "pipeline/raster.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"

namespace gsdot3::tools {

struct scored {
  double smooth = -1e9;  // wrap-side value in levels, real (the exact Σ n_c·L_c, no floors)
  int value = 0;         // the model's wrap-side value at the best pixel (>= 128: a wrap)
  int px = -1, py = -1;
};

// The best wrap-side pixel (side +1: value >= 128, −1: value <= −129, read as −value − 1 >= 128)
// among the covered pixels within `radius` of the vertices in `vertices` (bit k: vertex k): the
// model's exact value is computed at every one of them and ranks first, the smooth part second
// (a neighbouring pixel with a smaller smooth part can have kinder floors and wrap).
inline scored score_near_vertices(const proofs::two_pass::triangle::triangle_case& c, const gs::model_options& o,
                                  const proofs::two_pass::table& t, int side, int radius = 2, unsigned vertices = 7) {
  namespace tt = proofs::two_pass::triangle;
  namespace pl = pipeline;
  scored best;
  const auto setup = pl::setup_triangle(
      {pl::xy124{c.xy16[0], c.xy16[1]}, pl::xy124{c.xy16[2], c.xy16[3]}, pl::xy124{c.xy16[4], c.xy16[5]}});
  if (setup.area2 == 0) return best;
  const auto nm = proofs::paper::pack_normal_from(c.iX, c.iY);
  const int e = t.alpha_error(nm);
  const int n[3] = {nm.iX, nm.iY, nm.iZ};
  for (int k = 0; k < 3; ++k) {
    if ((vertices >> k & 1) == 0) continue;
    const int vx = c.xy16[2 * k] >> 4, vy = c.xy16[2 * k + 1] >> 4;
    for (int y = vy - radius; y <= vy + radius; ++y)
      for (int x = vx - radius; x <= vx + radius; ++x) {
        if (x < 0 || y < 0 || x >= tt::window_pixels || y >= tt::window_pixels || !pl::covers(setup, x, y)) continue;
        tt::triangle_case q = c;
        q.px = x, q.py = y;
        const auto L = tt::pixel_light(q);
        const int Lc[3] = {L.r.value(), L.g.value(), L.b.value()};
        double real = e;
        for (int ch = 0; ch < 3; ++ch) {
          const int l = o.gouraud == gs::gouraud_fraction::truncate_to_8 ? (Lc[ch] >> 7) << 7 : Lc[ch];
          real += n[ch] * (l - 16384) / 16384.0;
        }
        const double sm = side > 0 ? real : -real - 1;
        const auto r = proofs::two_pass::pixel(nm, L, o);
        const int v = side > 0 ? r.value : -r.value - 1;
        if (best.px < 0 || v > best.value || (v == best.value && sm > best.smooth)) best = {sm, v, x, y};
      }
  }
  return best;
}

// A case, its score and its wrap side; `better` ranks scores as score_near_vertices does.
struct found {
  proofs::two_pass::triangle::triangle_case c{};
  scored sc;
  int side = 1;
};
inline bool better(const scored& x, const scored& y) {
  return x.value > y.value || (x.value == y.value && x.smooth > y.smooth);
}

// The case under a sign pattern: n_x negated if fx = −1, n_y if fy = −1, the wrap side if fs = −1;
// channel c of every light is negated where σ_c = sign n_c · side changes, so every folded value
// σ_c·(L_c − 128) and the geometry stay as they are (the GS's truncations toward zero are odd) and
// only the floors and the alpha error move.
inline proofs::two_pass::triangle::triangle_case flipped(proofs::two_pass::triangle::triangle_case c, int fx, int fy,
                                                         int fs) {
  const int f[3] = {fx * fs, fy * fs, fs};
  c.iX *= fx, c.iY *= fy;
  for (auto& l : c.light)
    for (std::size_t ch = 0; ch < 3; ++ch) l[ch] *= f[ch];
  return c;
}

// The best score of case c (wrap side `side`, pixels near the vertices in `vertices`) over the
// Appendix 2 normals within ±nr of its own (same signs) and, with `signs`, every sign pattern.
inline found explore(const proofs::two_pass::triangle::triangle_case& c, int side, int nr, bool signs,
                     const gs::model_options& o, const proofs::two_pass::table& t,
                     const std::set<std::pair<int, int>>& normals, unsigned vertices = 4) {
  found best{c, score_near_vertices(c, o, t, side, 2, vertices), side};
  for (int fs = 1; fs >= (signs ? -1 : 1); fs -= 2)
    for (int fy = 1; fy >= (signs ? -1 : 1); fy -= 2)
      for (int fx = 1; fx >= (signs ? -1 : 1); fx -= 2)
        for (int dy = -nr; dy <= nr; ++dy)
          for (int dx = -nr; dx <= nr; ++dx) {
            auto q = c;
            q.iX += dx, q.iY += dy;
            if (q.iX * c.iX <= 0 || q.iY * c.iY <= 0) continue;
            q = flipped(q, fx, fy, fs);
            if ((fx == 1 && fy == 1 && fs == 1 && dx == 0 && dy == 0) || !normals.count({q.iX, q.iY})) continue;
            const scored sc = score_near_vertices(q, o, t, side * fs, 2, vertices);
            if (better(sc, best.sc)) best = {q, sc, side * fs};
          }
  return best;
}

// One certificate row: certificates.csv's first twenty columns, in order (the pixel from `at`); `what` names the
// row in its heading ("wrap", or "best" for a search's best case that does not wrap).
inline void print_certificate_row(const proofs::two_pass::triangle::triangle_case& k, const scored& at,
                                  const char* option, const char* what = "wrap") {
  std::printf(
      "s = %d (%s): %s at pixel (%d, %d)\n    {%d, %d, %d, {{{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}}}, {%d, %d, %d, "
      "%d, %d, %d}, %d, %d},\n",
      k.s, option, what, at.px, at.py, k.s, k.iX, k.iY, k.light[0][0], k.light[0][1], k.light[0][2], k.light[1][0],
      k.light[1][1], k.light[1][2], k.light[2][0], k.light[2][1], k.light[2][2], k.xy16[0], k.xy16[1], k.xy16[2],
      k.xy16[3], k.xy16[4], k.xy16[5], at.px, at.py);
}

}  // namespace gsdot3::tools
