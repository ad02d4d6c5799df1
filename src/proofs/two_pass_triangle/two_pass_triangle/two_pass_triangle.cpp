#include "two_pass_triangle/two_pass_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "gs_arith/gouraud.hpp"
#include "gs_arith/rasteriser.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::two_pass::triangle {

gs::rgba8 light_colour(const ivec3& l) noexcept {
  return {methods::byte(128 + l[0]), methods::byte(128 + l[1]), methods::byte(128 + l[2]), methods::byte(0x80)};
}

gs::fragment_colour pixel_light(const triangle_case& c, gs::gouraud_setup setup) noexcept {
  std::array<gs::gouraud_vertex, 3> v{};
  for (std::size_t k = 0; k < 3; ++k)
    v[k] = {c.xy16[2 * k] + xy_offset_pixels * 16, c.xy16[2 * k + 1] + xy_offset_pixels * 16, light_colour(c.light[k])};
  const auto r = reference_pixel(c.xy16);
  const auto plane = gs::gouraud_triangle(v[0], v[1], v[2], r[0] + xy_offset_pixels, r[1] + xy_offset_pixels);
  if (!plane) return gs::fragment_colour::flat(light_colour(c.light[2]));  // zero area: covers nothing
  auto at = *plane;
  at.clip_x0 = xy_offset_pixels;  // SCISSOR: the window's left edge
  return gs::gouraud_colour(at, c.px + xy_offset_pixels, c.py + xy_offset_pixels, setup);
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
};
normal_terms terms(const paper::packed_normal& p) {
  const std::int64_t c[3] = {std::abs(p.iX), std::abs(p.iY), std::abs(p.iZ)};
  std::int64_t least = 1 << 30;
  for (std::int64_t v : c)
    if (v != 0) least = std::min(least, v);
  return {isqrt_ceil(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), c[0] + c[1] + c[2], least};
}

// The largest s (0 .. 127) for which the bound of cannot_wrap holds for this normal: the reach
// len·s·128 + G grows with s, so that is every s below the least failing one.
// Other set-ups: the ball's reach len·s·128 + l1·W (len >= |n|), and under pcsx2_rows the cube's
// l1·(128·s + 3) as well.
int safe_s(const paper::packed_normal& p, const normal_terms& n, int e, const gs::model_options& o) {
  const bool steps = o.setup == gs::gouraud_setup::plane_steps;
  const std::int64_t err = steps ? gain_units(n.l1, n.least, lag_window(o)) : n.l1 * lag_window(o);
  const std::int64_t top = wrap_threshold_units(p, e, 1, o) - truncation_units(p, 1, o),
                     bottom = wrap_threshold_units(p, e, -1, o) - truncation_units(p, -1, o);
  const std::int64_t room = std::min(top, bottom) - 1;  // reach <= room
  if (room - err < 0) return 0;
  std::int64_t s = std::min<std::int64_t>(127, (room - err) / (n.len * 128));
  if (saturates(o)) s = room - 3 * n.l1 < 0 ? 0 : std::min(s, (room - 3 * n.l1) / (n.l1 * 128));
  return static_cast<int>(s);
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

std::int64_t ball_reach_units(const std::array<std::int64_t, 3>& n, int s, int window) {
  const std::int64_t radius = std::int64_t{128} * s;  // R² <= 2^28, |n|² <= 2^15
  return isqrt_ceil(radius * radius * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2])) + (n[0] + n[1] + n[2]) * window;
}

std::int64_t reach_units(const std::array<std::int64_t, 3>& n, int s, int window) {
  const std::int64_t radius = std::int64_t{128} * s;
  std::int64_t reach = ball_reach_units(n, s, window);  // (i)
  const unsigned nonzero = (n[0] != 0) | (n[1] != 0) << 1 | (n[2] != 0) << 2;
  for (unsigned d = 1; d < 8; ++d)
    if ((d & nonzero) == d && d != nonzero) reach = std::max(reach, two_point_units(n, d, radius, window));
  return reach;
}

std::int64_t light_support(const std::array<std::int64_t, 3>& n, std::span<const ivec3> lights) noexcept {
  std::int64_t best = 0;
  for (const auto& l : lights)
    best = std::max(best, n[0] * std::abs(l[0]) + n[1] * std::abs(l[1]) + n[2] * std::abs(l[2]));
  return best;
}

std::vector<ivec3> ball_support_lights(int s) {
  // light_support takes |l_c| and n_c >= 0, so over the ball's cells it is the largest n·l over the
  // cells of the first octant with the largest z for their (x, y): for fixed x, y the sum grows with z.
  std::vector<ivec3> out;
  for (int x = 0; x <= s; ++x)
    for (int y = 0; x * x + y * y <= s * s; ++y) {
      int z = 0;
      while (x * x + y * y + (z + 1) * (z + 1) <= s * s) ++z;
      out.push_back({x, y, z});
    }
  return out;
}

bool cannot_wrap(const paper::packed_normal& p, int e, int s, const gs::model_options& o,
                 std::span<const ivec3> lights) noexcept {
  // value < reach/16384 + neg + e, compared without division.
  const std::array<std::int64_t, 3> n{std::abs(p.iX), std::abs(p.iY), std::abs(p.iZ)};
  auto fits = [&](std::int64_t reach) {
    return reach + truncation_units(p, 1, o) < wrap_threshold_units(p, e, 1, o) &&
           reach + truncation_units(p, -1, o) < wrap_threshold_units(p, e, -1, o);
  };
  if (o.setup == gs::gouraud_setup::plane_steps) return fits(reach_units(n, s, window_pixels));
  if (saturates(o) && !fits(saturation_units(n, s))) return false;
  // the ball first; the light set's support (a scan of it) only where the ball is not enough
  const int w = lag_window(o);
  return fits(ball_reach_units(n, s, w)) ||
         (!lights.empty() && fits(128 * light_support(n, lights) + (n[0] + n[1] + n[2]) * w));
}

int bound_safe_s(const gs::model_options& o, bool attenuated) {
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
  for (const auto& p : appendix2_normals())
    order.push_back({safe_s(p, terms(p), t.alpha_error(p), o), &p, t.alpha_error(p)});
  std::sort(order.begin(), order.end(), [](const start& a, const start& b) { return a.s < b.s; });
  // The light sets per s, built when a set-up other than plane_steps first asks for one.
  std::map<int, std::vector<ivec3>> sets;
  auto lights = [&](int s) -> std::span<const ivec3> {
    // plane_steps has its own bound; under pcsx2_rows the cube of the saturated steps decides, not the ball
    if (o.setup == gs::gouraud_setup::plane_steps || saturates(o)) return {};
    auto it = sets.find(s);
    if (it == sets.end()) it = sets.emplace(s, attenuated ? ball_support_lights(s) : packed_lights(s)).first;
    return it->second;
  };
  int least = 127;
  for (const auto& k : order) {
    if (k.s >= least) break;
    if (least < 127 && cannot_wrap(*k.p, k.e, least, o, lights(least))) continue;
    int s = k.s;
    while (s < least && cannot_wrap(*k.p, k.e, s + 1, o, lights(s + 1))) ++s;
    least = std::min(least, s);
  }
  return least;
}

std::array<int, 2> reference_pixel(const std::array<int, 6>& xy16) noexcept {
  return {gs::ceil_124(std::min({xy16[0], xy16[2], xy16[4]})), gs::ceil_124(std::min({xy16[1], xy16[3], xy16[5]}))};
}

lag_edge lag_edge_of(const std::array<int, 6>& xy16) noexcept {
  lag_edge e;
  for (std::size_t k = 1; k < 3; ++k) {
    if (xy16[2 * k] < xy16[2 * e.X]) e.X = k;
    if (xy16[2 * k + 1] < xy16[2 * e.Y + 1]) e.Y = k;
  }
  const auto r = reference_pixel(xy16);
  e.rx = r[0], e.ry = r[1];
  e.xi = xy16[2 * e.X] - 16 * e.rx, e.bX = xy16[2 * e.X + 1] - 16 * e.ry;
  e.aY = xy16[2 * e.Y] - 16 * e.rx, e.eta = xy16[2 * e.Y + 1] - 16 * e.ry;
  return e;
}

plane_point point_w(const lag_edge& e, int px, int py) noexcept {
  // w(t)·16 − 16·r = (ξ + t·(a_Y − ξ), b_X + t·(η − b_X)): x grows with t, y falls; t = num/den,
  // the comparisons multiplied through by den > 0.
  const std::int64_t a16 = 16 * std::int64_t{px - e.rx}, b16 = 16 * std::int64_t{py - e.ry};
  const std::int64_t cand[4][2] = {{0, 1}, {1, 1}, {a16 - e.xi, e.aY - e.xi}, {e.bX - b16, e.bX - e.eta}};
  plane_point w;
  for (const auto& t : cand) {
    if (t[1] <= 0 || t[0] < 0 || t[0] > t[1]) continue;
    const bool below_x = e.xi * (t[1] - t[0]) + e.aY * t[0] <= a16 * t[1];
    const bool below_y = e.bX * (t[1] - t[0]) + e.eta * t[0] <= b16 * t[1];
    if (below_x && below_y && (w.at_pixel() || t[0] * w.den < w.num * t[1])) w = {t[0], t[1]};
  }
  return w;
}

}  // namespace gsdot3::proofs::two_pass::triangle
