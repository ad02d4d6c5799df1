// proofs_triangle_score.hpp — the exact score the triangle certificate searches share: a case's
// covered pixels next to its vertices, each light through tt::pixel_light and the pixel through the
// model's two-pass passes (two_pass::pixel), and the certificate row in the table's format
// (src/proofs/proofs/two_pass_triangle.cpp).
#pragma once

#include <cstdio>

#include "pipeline/raster.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"
#include "proofs/two_pass_triangle.hpp"

namespace gsdot3::bench {

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
  const auto setup = pl::setup_triangle({pl::xy124{c.xy16[0], c.xy16[1]}, pl::xy124{c.xy16[2], c.xy16[3]}, pl::xy124{c.xy16[4], c.xy16[5]}});
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

// One certificate row, as in two_pass_triangle.cpp's table (the pixel from `at`); `what` names the
// row in its heading ("wrap", or "best" for a search's best case that does not wrap).
inline void print_certificate_row(const proofs::two_pass::triangle::triangle_case& k, const scored& at, const char* option,
                                  const char* what = "wrap") {
  std::printf("s = %d (%s): %s at pixel (%d, %d)\n    {%d, %d, %d, {{{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}}}, {%d, %d, %d, %d, %d, %d}, %d, %d},\n",
              k.s, option, what, at.px, at.py, k.s, k.iX, k.iY, k.light[0][0], k.light[0][1], k.light[0][2], k.light[1][0], k.light[1][1],
              k.light[1][2], k.light[2][0], k.light[2][1], k.light[2][2], k.xy16[0], k.xy16[1], k.xy16[2], k.xy16[3], k.xy16[4], k.xy16[5],
              at.px, at.py);
}

}  // namespace gsdot3::bench
