// proofs_triangle two-axis — triangle certificates of two-pass.max-s.interpolated whose pixel lags
// along both axes (src/proofs/two_pass_triangle/two_pass_triangle/two_pass_triangle.hpp, case (ii) of the bound). Not a
// benchmark and not a test: a reproducible tool; every row it prints is re-verified by the claim and replayed through
// the rasteriser in tests/proofs/triangle_test.cpp.
//
//   proofs_triangle two-axis S [--truncate-to-8]
// The construction: X = (0, E), Y = (E, 0), Z = (E, E) (12.4, E = 32752: the reference pixel is the
// window's corner, Z's pixel lies ~2046 pixels from it along both axes), l_X = l_Y = l_Z + d with d
// along the wrap side's signs σ: on the two channels of largest |n_c| d_c = D levels, whose step
// 128·D/2047 units per pixel truncates to 0 (D <= 15), so the pixel keeps the value at the corner,
// D levels above l_Z per axis (2·D in all); on the third channel d_c = −16·k, whose step is an
// integer plus 0.0005 and loses nothing, chosen so that n·d ≈ 0 (the plane stays level along n and
// l_Z can sit near the top of the sphere). For every Appendix 2 normal with both sign patterns and
// each k, the lights l_Z of L_S with l_Z + d in L_S are scanned (those whose vertex value is within
// 40 of the wrap) and the covered pixels next to Z evaluated through gs::gouraud_triangle and the
// model's two-pass passes. Prints the first wrapping case as a certificate row.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pipeline/raster.hpp"
#include "proofs/domains.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"
#include "triangle_args.hpp"

namespace p = gsdot3::proofs;
namespace pl = gsdot3::pipeline;
namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
int run(const gsdot3::tools::search_args& args) {
  const int s = args.s;
  const gs::model_options o = args.options();
  constexpr int E = (tt::window_pixels - 1) * 16;
  const std::array<int, 6> xy16{0, E, E, 0, E, E};
  const auto setup = pl::setup_triangle({pl::xy124{0, E}, pl::xy124{E, 0}, pl::xy124{E, E}});
  std::vector<std::pair<int, int>> pixels;  // covered pixels within 2 of Z
  for (int y = tt::window_pixels - 3; y < tt::window_pixels; ++y)
    for (int x = tt::window_pixels - 3; x < tt::window_pixels; ++x)
      if (pl::covers(setup, x, y)) pixels.push_back({x, y});
  const p::two_pass::table t(o);
  long long evaluated = 0;
  int best = -1000;
  for (int D = 15; D >= 12; --D)
    for (const auto& nm : p::appendix2_normals())
      for (int side : {1, -1}) {
        const int n[3] = {nm.iX, nm.iY, nm.iZ};
        int sigma[3];
        for (int c = 0; c < 3; ++c) sigma[c] = (n[c] >= 0 ? 1 : -1) * side;
        int comp = 0;  // the channel of least |n_c| compensates
        for (int c = 1; c < 3; ++c)
          if (std::abs(n[c]) < std::abs(n[comp])) comp = c;
        // k with 16·k·|n_comp| closest to D·(|n_a| + |n_b|)
        const int rise = D * (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]) - std::abs(n[comp]));
        if (n[comp] == 0) continue;
        const int k = (rise + 8 * std::abs(n[comp])) / (16 * std::abs(n[comp]));
        if (k < 1 || 16 * k > 2 * s) continue;
        p::ivec3 d{};
        for (int c = 0; c < 3; ++c) d[static_cast<std::size_t>(c)] = sigma[c] * (c == comp ? -16 * k : D);
        // l_Z near c·n̂ − d⊥/2 (σ-side), the point that lets l_Z and l_Z + d both sit near the top
        double nh[3], len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]), nd = 0;
        for (int c = 0; c < 3; ++c) nh[c] = side * n[c] / len, nd += nh[c] * d[static_cast<std::size_t>(c)];
        double perp2 = 0, dp[3];
        for (int c = 0; c < 3; ++c) dp[c] = d[static_cast<std::size_t>(c)] - nd * nh[c], perp2 += dp[c] * dp[c];
        if (perp2 / 4 >= double(s) * s) continue;
        const double cz = std::sqrt(double(s) * s - perp2 / 4);
        const int cx = static_cast<int>(std::lround(cz * nh[0] - dp[0] / 2)),
                  cy = static_cast<int>(std::lround(cz * nh[1] - dp[1] / 2)),
                  cw = static_cast<int>(std::lround(cz * nh[2] - dp[2] / 2));
        for (int i = -2; i <= 2; ++i)
          for (int j = -2; j <= 2; ++j)
            for (int l = -2; l <= 2; ++l) {
              const p::ivec3 lz{cx + i, cy + j, cw + l};
              if (!p::is_packed_light(s, lz)) continue;
              const p::ivec3 lx{lz[0] + d[0], lz[1] + d[1], lz[2] + d[2]};
              if (!p::is_packed_light(s, lx)) continue;
              for (const auto& [x, y] : pixels) {
                const tt::triangle_case c{s, nm.iX, nm.iY, {lx, lx, lz}, xy16, x, y};
                const auto r = p::two_pass::pixel(nm, tt::pixel_light(c), o);
                ++evaluated;
                best = std::max(best, side > 0 ? r.value : -r.value - 1);
                if (r.value != r.dot) {
                  std::printf(
                      "s = %d (%s): wrap, value %d (%lld cases evaluated)\n"
                      "    {%d, %d, %d, {{{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}}}, {0, %d, %d, 0, %d, %d}, %d, "
                      "%d},\n",
                      s, args.option_name(), r.value, evaluated, s, nm.iX, nm.iY, lx[0], lx[1], lx[2], lx[0], lx[1],
                      lx[2], lz[0], lz[1], lz[2], E, E, E, E, x, y);
                  return 0;
                }
              }
            }
      }
  std::printf("s = %d: no wrapping pixel in the searched set (%lld cases, best wrap-side value %d)\n", s, evaluated,
              best);
  return 1;
}
}  // namespace

void gsdot3::tools::add_two_axis_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<search_args>();
  CLI::App* cmd =
      app.add_subcommand("two-axis", "The two-axis construction: the certificate rows at s = 91 (one per option)");
  cmd->footer(
      "Prints the first wrapping case as a certificate row (exit status 0), or the best wrap-side value (1). Seconds.");
  add_search_args(*cmd, *args);
  cmd->callback([args, &rc] { rc = run(*args); });
}
