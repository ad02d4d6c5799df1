// proofs_triangle search — finds the triangle certificates of two-pass.max-s.interpolated
// (src/proofs/proofs/claims_two_pass.cpp) at s = 100 and 122..125. Not a test: a reproducible tool.
//
//   proofs_triangle search S [--truncate-to-8]
// The construction (argument in src/proofs/two_pass_triangle/two_pass_triangle/two_pass_triangle.hpp): a right triangle
// A = (W, 0), B = (0, H), C = (W, H) in the 2048² window, so the plane's reference pixel (the
// bounding box's top-left, as the pipeline sets it up) is the bbox corner (0, 0) and a pixel next to
// A lies a ≈ W pixels from it. Its x step per channel is trunc(128·(l_C − l_B)/W): the truncated
// fraction, times a, is missing from the pixel's light, up to 16 levels per channel for W ≈ 2047.
// For each sign pattern of the normal (and the top wrap value >= 128 or the bottom one <= −129) the
// tool picks W and l_C − l_B so that the three fractions are near 1 and point along ±n, finds shell
// lights l_B, l_C with that difference, and then every Appendix 2 normal with that pattern × every
// packed light l_A of L_S, evaluating the pixel next to A through gs::gouraud_triangle and the
// model's two-pass passes. Prints the first wrapping case as a certificate row, or that none exists
// in the searched set. Seconds of CPU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gs_arith/gouraud.hpp"
#include "pipeline/raster.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "triangle_args.hpp"

namespace p = gsdot3::proofs;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
int run(const gsdot3::tools::search_args& args) {
  const int s = args.s;
  const gs::model_options o = args.options();
  const auto& normals = p::appendix2_normals();
  const p::two_pass::table t(o);
  const auto lights = p::packed_lights(s);
  auto is_light = [&](const p::ivec3& l) { return std::binary_search(lights.begin(), lights.end(), l); };
  long long evaluated = 0;
  int best_top = -1000, best_bottom = 1000;
  for (int top = 1; top >= 0; --top)
    for (int sx = 0; sx < 2; ++sx)
      for (int sy = 0; sy < 2; ++sy) {
        // sign of n: x, y from the pattern, z > 0. The step's sign must be −sign(n) (top) or +sign(n)
        // (bottom) so that the missing fraction moves the light along +n or −n.
        const int sn[3] = {sx ? 1 : -1, sy ? 1 : -1, 1};
        for (int W16 = 32752; W16 >= 30000; W16 -= 1) {
          // per channel the least difference m whose step fraction frac(2048·m/W16) is >= 0.99
          p::ivec3 D{};
          bool all = true;
          for (int c = 0; c < 3; ++c) {
            int m = 1;
            for (; m <= 2 * s; ++m) {
              const double g = 2048.0 * m / W16;
              if (g - std::floor(g) >= 0.99) break;
            }
            all = all && m <= 2 * s;
            D[static_cast<std::size_t>(c)] = (top ? -sn[c] : sn[c]) * m;
          }
          if (!all) continue;
          const p::ivec3* lb = nullptr;
          p::ivec3 lc{};
          for (const auto& l : lights) {
            const p::ivec3 c{l[0] + D[0], l[1] + D[1], l[2] + D[2]};
            if (is_light(c)) {
              lb = &l, lc = c;
              break;
            }
          }
          if (lb == nullptr) continue;
          const int H16 = 32752;
          namespace pl = gsdot3::pipeline;
          const auto setup = pl::setup_triangle({pl::xy124{W16, 0}, pl::xy124{0, H16}, pl::xy124{W16, H16}});
          int px = -1, py = -1;  // the covered pixel nearest A: top rows first, then rightmost
          for (int y = 0; y < 4 && px < 0; ++y)
            for (int x = W16 / 16; x >= W16 / 16 - 3 && px < 0; --x)
              if (pl::covers(setup, x, y)) px = x, py = y;
          if (px < 0) continue;
          for (const auto& nm : normals) {
            if ((nm.iX >= 0) != (sx == 1) || (nm.iY >= 0) != (sy == 1)) continue;
            const int e = t.alpha_error(nm);
            for (const auto& la : lights) {
              const long nl = static_cast<long>(nm.iX) * la[0] + static_cast<long>(nm.iY) * la[1] +
                              static_cast<long>(nm.iZ) * la[2];
              // only lights whose vertex value is within 26 of the wrap (the construction adds < 28)
              if (top ? nl / 128 + e < 100 : nl / 128 + e > -101) continue;
              const tt::triangle_case k{s, nm.iX, nm.iY, {la, *lb, lc}, {W16, 0, 0, H16, W16, H16}, px, py};
              ++evaluated;
              const auto light = tt::pixel_light(k);
              const auto r = p::two_pass::pixel(nm, light, o);
              best_top = std::max(best_top, r.value), best_bottom = std::min(best_bottom, r.value);
              if (r.value != r.dot) {
                std::printf(
                    "s = %d (%s): wrap, value %d, DPB dot %d (%lld cases evaluated)\n"
                    "    {%d, %d, %d, {{{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}}}, {%d, 0, 0, %d, %d, %d}, %d, %d},\n",
                    s, args.option_name(), r.value, r.dot, evaluated, s, nm.iX, nm.iY, la[0], la[1], la[2], (*lb)[0],
                    (*lb)[1], (*lb)[2], lc[0], lc[1], lc[2], W16, H16, W16, H16, px, py);
                return 0;
              }
            }
          }
          break;  // one W per pattern: the largest W whose fractions are all near 1
        }
      }
  std::printf("s = %d: no wrapping pixel in the searched set (%lld cases, values %d .. %d)\n", s, evaluated,
              best_bottom, best_top);
  return 1;
}
}  // namespace

void gsdot3::tools::add_search_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<search_args>();
  CLI::App* cmd = app.add_subcommand(
      "search", "The one-axis construction: the certificate rows at s = 100 (one per option) and 122..125");
  cmd->footer(
      "Prints the first wrapping case as a certificate row (exit status 0), or that the searched set has none (1). "
      "Seconds.");
  add_search_args(*cmd, *args);
  cmd->callback([args, &rc] { rc = run(*args); });
}
