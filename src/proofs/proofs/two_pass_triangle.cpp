#include "proofs/two_pass_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gs_arith/gouraud.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::two_pass::triangle {

namespace {
constexpr triangle_case certificate_table[] = {
    {89, -73, -87, {{{-56, -68, 11}, {-56, -68, -4}, {-40, -52, 60}}}, {0, 32551, 32721, 0, 32752, 32744}, 2046, 2046},
    {89, 67, 81, {{{-11, -68, -56}, {4, -68, -56}, {-60, -52, -40}}}, {0, 32704, 32735, 0, 32752, 32752}, 2046, 2046},  // truncate_to_8
    {90, -77, -61, {{{-63, -12, 63}, {-63, -12, 63}, {-48, -59, 48}}}, {0, 32752, 32752, 0, 32368, 32466}, 2023, 2029},
    {90, -72, -63, {{{-57, -12, 68}, {-57, -14, 68}, {-42, -59, 53}}}, {761, 31626, 32752, 578, 31534, 32511}, 1968, 2029},  // truncate_to_8
    {91, -93, -50, {{{-69, -11, 58}, {-69, -11, 58}, {-54, -59, 43}}}, {0, 32752, 32752, 0, 32752, 32752}, 2046, 2045},
    {91, -93, -50, {{{-69, -11, 58}, {-69, -11, 58}, {-54, -59, 43}}}, {0, 32752, 32752, 0, 32752, 32752}, 2045, 2045},  // truncate_to_8
    {98, -61, -77, {{{-80, -34, 44}, {-45, -59, 64}, {38, 68, -58}}}, {0, 30957, 32752, 385, 30742, 30271}, 2046, 25},
    {98, -77, -78, {{{-49, -38, 75}, {-59, -60, 50}, {40, 66, -59}}}, {31163, 0, 0, 32752, 31518, 30185}, 2, 2045},  // truncate_to_8
    {100, -105, -54, {{{-82, -46, 34}, {-77, -48, 42}, {34, 63, -69}}}, {32521, 0, 0, 32752, 32521, 32752}, 2032, 1},
    {100, -106, -58, {{{-82, -46, 34}, {-77, -48, 42}, {34, 63, -69}}}, {32521, 0, 0, 32752, 32521, 32752}, 2032, 1},  // truncate_to_8
    {122, -127, -15, {{{-122, 0, 0}, {-106, -46, 39}, {21, 81, -88}}}, {32552, 0, 0, 32752, 32552, 32752}, 2034, 1},
    {123, -127, -15, {{{-123, 0, 0}, {-108, -44, 39}, {19, 83, -88}}}, {32552, 0, 0, 32752, 32552, 32752}, 2034, 1},
    {124, -127, -15, {{{-124, 0, 0}, {-109, -49, 33}, {18, 78, -94}}}, {32552, 0, 0, 32752, 32552, 32752}, 2034, 1},
    {125, -127, -15, {{{-125, 0, 0}, {-83, -69, 63}, {60, 74, -80}}}, {32576, 0, 0, 32752, 32576, 32752}, 2035, 2},
};
}  // namespace

std::span<const triangle_case> certificates() noexcept { return certificate_table; }

gs::rgba8 light_colour(const ivec3& l) noexcept {
  return {methods::byte(128 + l[0]), methods::byte(128 + l[1]), methods::byte(128 + l[2]), methods::byte(0x80)};
}

namespace {
// ceil(v / 16) for a 12.4 value (pipeline/raster.hpp ceil_124).
constexpr int ceil_124(int v) noexcept { return static_cast<int>((static_cast<std::int64_t>(v) + 15) >> 4); }
}  // namespace

gs::fragment_colour pixel_light(const triangle_case& c) noexcept {
  std::array<gs::gouraud_vertex, 3> v{};
  int x_ref = 1 << 16, y_ref = 1 << 16;
  for (std::size_t k = 0; k < 3; ++k) {
    const int x = c.xy16[2 * k], y = c.xy16[2 * k + 1];
    v[k] = {x + xy_offset_pixels * 16, y + xy_offset_pixels * 16, light_colour(c.light[k])};
    x_ref = std::min(x_ref, ceil_124(x));
    y_ref = std::min(y_ref, ceil_124(y));
  }
  const auto plane = gs::gouraud_triangle(v[0], v[1], v[2], x_ref + xy_offset_pixels, y_ref + xy_offset_pixels);
  if (!plane) return gs::fragment_colour::flat(light_colour(c.light[2]));  // zero area: covers nothing
  return gs::gouraud_at(*plane, c.px + xy_offset_pixels, c.py + xy_offset_pixels);
}

namespace {
std::int64_t isqrt_ceil(std::int64_t v) {
  std::int64_t r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r < v) ++r;
  while (r > 0 && (r - 1) * (r - 1) >= v) --r;
  return r;
}
}  // namespace

namespace {
struct normal_terms {
  std::int64_t len, l1, least;  // ceil |n|, |n|_1, the least nonzero |n_c|
  int neg;                      // #{n_c < 0}
};
normal_terms terms(const paper::packed_normal& p) {
  const std::int64_t c[3] = {std::abs(p.iX), std::abs(p.iY), std::abs(p.iZ)};
  std::int64_t least = 1 << 30;
  for (std::int64_t v : c)
    if (v != 0) least = std::min(least, v);
  return {isqrt_ceil(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), c[0] + c[1] + c[2], least, (p.iX < 0) + (p.iY < 0) + (p.iZ < 0)};
}

// The largest s (0 .. 127) for which the bound of cannot_wrap holds for this normal: the reach
// len·s·128 + G grows with s, so that is every s below the least failing one.
int safe_s(const normal_terms& n, int e, const gs::model_options& o) {
  const std::int64_t err = gain_units(n.l1, n.least, window_pixels, o);
  const std::int64_t top = std::int64_t{16384} * (128 - n.neg - e) - err, bottom = std::int64_t{16384} * (129 - (3 - n.neg) + e) - err;
  const std::int64_t room = std::min(top, bottom) - 1;  // reach <= room
  if (room < 0) return 0;
  return static_cast<int>(std::min<std::int64_t>(127, room / (n.len * 128)));
}
}  // namespace

std::int64_t two_point_units(const std::array<std::int64_t, 3>& n, unsigned in_d, std::int64_t radius, int window) {
  // θ_c = k_c / steps; the bound ×steps: R·(|steps·α| + |steps·β|) + steps·K, square roots rounded up.
  constexpr int steps = 16;
  const std::int64_t W = window;
  int k[3] = {steps, steps, steps};
  std::int64_t best = -1;
  const int grid[3] = {(in_d & 1) ? steps : 0, (in_d & 2) ? steps : 0, (in_d & 4) ? steps : 0};
  for (k[0] = grid[0]; k[0] >= 0; --k[0])
    for (k[1] = grid[1]; k[1] >= 0; --k[1])
      for (k[2] = grid[2]; k[2] >= 0; --k[2]) {
        std::int64_t a2 = 0, b2 = 0, K = 0;
        for (std::size_t c = 0; c < 3; ++c) {
          const std::int64_t kc = (in_d >> c & 1) ? k[c] : steps, a = kc * n[c], b = (steps - kc) * n[c];
          a2 += a * a, b2 += b * b;
          K += (in_d >> c & 1) ? n[c] * (kc * (2 * W - 1) + (steps - kc) * W) : n[c] * steps * W;
        }
        const std::int64_t v = (radius * (isqrt_ceil(a2) + isqrt_ceil(b2)) + K + steps - 1) / steps;
        if (best < 0 || v < best) best = v;
      }
  return best;
}

std::int64_t reach_units(const std::array<std::int64_t, 3>& n, int s, int window, const gs::model_options& o) {
  const std::int64_t radius = std::int64_t{128} * s, l1 = n[0] + n[1] + n[2];
  std::int64_t reach = radius * isqrt_ceil(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + l1 * window;  // (i)
  const unsigned nonzero = (n[0] != 0) | (n[1] != 0) << 1 | (n[2] != 0) << 2;
  for (unsigned d = 1; d < 8; ++d)
    if ((d & nonzero) == d && d != nonzero) reach = std::max(reach, two_point_units(n, d, radius, window));
  return reach + (o.gouraud == gs::gouraud_fraction::keep_fraction ? 0 : 128 * l1);
}

bool cannot_wrap(const paper::packed_normal& p, int e, int s, const gs::model_options& o) noexcept {
  const normal_terms n = terms(p);
  // value < reach/16384 + neg + e, compared without division.
  const std::int64_t reach = reach_units({std::abs(p.iX), std::abs(p.iY), std::abs(p.iZ)}, s, window_pixels, o);
  return reach < std::int64_t{16384} * (128 - n.neg - e) && reach < std::int64_t{16384} * (129 - (3 - n.neg) + e);
}

int bound_safe_s(const gs::model_options& o) {
  // (ii)'s s per normal first (fast, and reach_units <= its reach: θ = 1 is (ii)), then (iii) from
  // there, for the normals whose (ii) s is below the least found so far and that are not safe at
  // that least (reach grows with s, so a normal safe there cannot lower it).
  const two_pass::table t(o);
  struct start {
    int s;
    const paper::packed_normal* p;
    int e;
  };
  std::vector<start> order;
  for (const auto& p : appendix2_normals()) order.push_back({safe_s(terms(p), t.alpha_error(p), o), &p, t.alpha_error(p)});
  std::sort(order.begin(), order.end(), [](const start& a, const start& b) { return a.s < b.s; });
  int least = 127;
  for (const auto& k : order) {
    if (k.s >= least) break;
    if (least < 127 && cannot_wrap(*k.p, k.e, least, o)) continue;
    int s = k.s;
    while (s < least && cannot_wrap(*k.p, k.e, s + 1, o)) ++s;
    least = std::min(least, s);
  }
  return least;
}

triangle_case brute_force_case(std::uint64_t index) {
  static const std::vector<ivec3> lights = [] {
    const auto all = packed_lights(122);
    return std::vector<ivec3>{all[0], all[all.size() / 4], all[all.size() / 2], all[3 * all.size() / 4]};
  }();
  triangle_case c{0, 0, 0, {}, {}, 0, 0};
  const std::uint64_t light_part = index & 63, tri = index >> 6;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint64_t point = (tri >> (6 * k)) & 63;
    const int i = static_cast<int>(point & 7), j = static_cast<int>(point >> 3);
    c.xy16[2 * k] = std::min(4096 * i + 5 * i + 3 * j, (window_pixels - 1) * 16);
    c.xy16[2 * k + 1] = std::min(4096 * j + 7 * j + 2 * i, (window_pixels - 1) * 16);
    c.light[k] = lights[(light_part >> (2 * k)) & 3];
  }
  return c;
}

brute_force_acc brute_force(const sweep_config& cfg) {
  return sweep<brute_force_acc>(
      brute_force_cases, cfg,
      [](brute_force_acc& acc, std::uint64_t begin, std::uint64_t end) {
        for (std::uint64_t i = begin; i < end; ++i) {
          const triangle_case c = brute_force_case(i);
          const std::int64_t x0 = c.xy16[0], y0 = c.xy16[1];
          const std::int64_t ax = c.xy16[2] - x0, ay = c.xy16[3] - y0, bx = c.xy16[4] - x0, by = c.xy16[5] - y0;
          const std::int64_t det = ax * by - bx * ay;
          if (det == 0) continue;
          const std::int64_t sign = det > 0 ? 1 : -1, adet = det * sign;
          const int xmin = ceil_124(std::min({c.xy16[0], c.xy16[2], c.xy16[4]})), ymin = ceil_124(std::min({c.xy16[1], c.xy16[3], c.xy16[5]}));
          const int xmax = std::max({c.xy16[0], c.xy16[2], c.xy16[4]}) >> 4, ymax = std::max({c.xy16[1], c.xy16[3], c.xy16[5]}) >> 4;
          // the plane once (pixel_light's set-up, read per pixel)
          std::array<gs::gouraud_vertex, 3> v{};
          for (std::size_t k = 0; k < 3; ++k)
            v[k] = {c.xy16[2 * k] + xy_offset_pixels * 16, c.xy16[2 * k + 1] + xy_offset_pixels * 16, light_colour(c.light[k])};
          const auto plane = gs::gouraud_triangle(v[0], v[1], v[2], xmin + xy_offset_pixels, ymin + xy_offset_pixels);
          std::int64_t c0[3], d1[3], d2[3];
          for (std::size_t ch = 0; ch < 3; ++ch)
            c0[ch] = 128 + c.light[0][ch], d1[ch] = c.light[1][ch] - c.light[0][ch], d2[ch] = c.light[2][ch] - c.light[0][ch];
          bool bad = false;
          for (int y = ymin; y <= ymax; ++y)
            for (int x = xmin; x <= xmax; ++x) {
              const std::int64_t qx = 16 * x - x0, qy = 16 * y - y0;
              // barycentric numerators (×det): inside the closed triangle iff all have det's sign
              const std::int64_t u = (by * qx - bx * qy) * sign, w = (ax * qy - ay * qx) * sign;
              if (u < 0 || w < 0 || u + w > adet) continue;
              ++acc.pixels;
              const auto f = gs::gouraud_at(*plane, x + xy_offset_pixels, y + xy_offset_pixels);
              const int L[3] = {f.r.value(), f.g.value(), f.b.value()};
              const std::int64_t bound = 1 + (x - xmin) + (y - ymin);
              for (std::size_t ch = 0; ch < 3; ++ch) {
                const std::int64_t Pdet = 128 * (c0[ch] * adet + d1[ch] * u + d2[ch] * w);  // P_c·|det|
                const std::int64_t diff = std::abs(L[ch] * adet - Pdet);
                if (diff >= bound * adet) bad = true;
                acc.error_units.add(diff / adet, i);
                acc.ratio_ppm.add(static_cast<std::int64_t>(static_cast<double>(diff) / static_cast<double>(bound * adet) * 1e6), i);
              }
            }
          if (bad) acc.violations.add(i);
        }
      },
      std::uint64_t{1} << 16);
}

}  // namespace gsdot3::proofs::two_pass::triangle
