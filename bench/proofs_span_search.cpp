// proofs_span_search — the search that finds the span certificates of two-pass.max-s.interpolated
// (src/proofs/proofs/claims_two_pass.cpp). Not a benchmark and not a test: a reproducible tool.
//
//   proofs_span_search S [MAX_DIST] [MAX_PIXELS]
// For each Appendix 2 normal that could wrap (e = +1 with n_x, n_y < 0, or e = −1 with n_x, n_y >= 0,
// see two_pass::wrap_search), the vertex lights of L_S in its cap whose value bound is within 2 of
// wrapping; every ordered pair of them at Chebyshev distance <= MAX_DIST (default 3), every span
// length 2..MAX_PIXELS (default 128) and every inner pixel, through gs::gouraud_span/gouraud_at and
// the model's two-pass passes (an 8.7 per-channel table built through the model). Prints the first
// wrapping pixel in that order, or that none exists in the searched set. Minutes of CPU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "gs_arith/gouraud.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace p = gsdot3::proofs;
namespace m = gsdot3::proofs::methods;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: proofs_span_search S [MAX_DIST] [MAX_PIXELS]\n");
    return 2;
  }
  const int s = std::atoi(argv[1]), max_dist = argc > 2 ? std::atoi(argv[2]) : 3,
            max_pixels = argc > 3 ? std::atoi(argv[3]) : 128;
  if (s < 1 || s > 127 || max_dist < 1 || max_pixels < 2) {
    std::fprintf(stderr, "proofs_span_search: S in 1..127, MAX_DIST >= 1, MAX_PIXELS >= 2\n");
    return 2;
  }
  const gs::model_options o{};
  const auto& normals = p::appendix2_normals();
  const p::two_pass::table t(o);
  std::vector<short> channel(256 * 32768);  // (n, 8.7 light) -> pass-2 value, through the model
  for (int n = -127; n <= 128; ++n)
    for (int L = 0; L < 32768; ++L) {
      const auto c = gs::gouraud_channel::from_wrapped(L);
      const gs::fragment_colour light{c, c, c, gs::gouraud_channel::from_wrapped(0x80 << 7)};
      const auto dpb = m::two_pass_pass1(m::grey(std::max(n, 0), 0), light, o);
      channel[static_cast<std::size_t>((n + 127) * 32768 + L)] =
          static_cast<short>(m::two_pass_pass2_wide(m::grey(std::max(-n, 0), 0), light, dpb, o).wide.r.value());
    }
  auto ch = [&](int n, gs::gouraud_channel L) { return channel[static_cast<std::size_t>((n + 127) * 32768 + L.value())]; };
  const p::two_pass::light_grid g(s);
  long long evaluated = 0;
  for (const auto& nm : normals) {
    const int e = t.alpha_error(nm);
    const bool top = e == 1 && nm.iX < 0 && nm.iY < 0, bottom = e == -1 && nm.iX >= 0 && nm.iY >= 0;
    if (!top && !bottom) continue;
    std::vector<p::ivec3> cap;
    for (const auto& l : g.lights) {
      // within 2 of wrapping by the bounds of two_pass::wrap_search (n_z > 0: two negative
      // components at most for the top case, three non-negative ones for the bottom case)
      const long nl = static_cast<long>(nm.iX) * l[0] + static_cast<long>(nm.iY) * l[1] + static_cast<long>(nm.iZ) * l[2];
      const bool near = top ? static_cast<int>(std::floor((nl + 254.0) / 128.0)) + e >= 126
                            : -static_cast<int>(std::floor((-nl + 381.0) / 128.0)) + e <= -127;
      if (near) cap.push_back(l);
    }
    auto colour = [](const p::ivec3& l) {
      return gs::rgba8{m::byte(128 + l[0]), m::byte(128 + l[1]), m::byte(128 + l[2]), m::byte(0x80)};
    };
    for (const auto& a : cap)
      for (const auto& b : cap) {
        if (a == b || std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])}) > max_dist) continue;
        for (int n = 2; n <= max_pixels; ++n) {
          const auto span = gs::gouraud_span(colour(a), colour(b), n);
          for (int k = 1; k < n; ++k) {
            const auto f = gs::gouraud_at(span, k);
            ++evaluated;
            const int v = ch(nm.iX, f.r) + ch(nm.iY, f.g) + ch(nm.iZ, f.b) + 3 * t.alpha(nm.alpha) - 384;
            if (v >= 128 || v <= -129) {
              const auto r = p::two_pass::pixel(nm, f, o);
              std::printf("s = %d: wrap at n = (%d, %d, %d), l0 = (%d, %d, %d), l1 = (%d, %d, %d), span %d, pixel %d: "
                          "value %d, DPB dot %d (%lld pixels evaluated)\n",
                          s, nm.iX, nm.iY, nm.iZ, a[0], a[1], a[2], b[0], b[1], b[2], n, k, r.value, r.dot, evaluated);
              return 0;
            }
          }
        }
      }
  }
  std::printf("s = %d: no wrapping pixel in the searched set (%lld pixels evaluated)\n", s, evaluated);
  return 0;
}
