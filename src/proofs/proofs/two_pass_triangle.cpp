#include "proofs/two_pass_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gs_arith/gouraud.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace gsdot3::proofs::two_pass::triangle {

namespace {
constexpr triangle_case certificate_table[] = {
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
// The largest s (0 .. 127) for which the bound of cannot_wrap holds for this normal: the reach
// len·s·128 + l1·E grows with s, so that is every s below the least failing one.
int safe_s(std::int64_t len, std::int64_t l1, int neg, int e, const gs::model_options& o) {
  const std::int64_t err = l1 * max_error_units(o);
  const std::int64_t top = std::int64_t{16384} * (128 - neg - e) - err, bottom = std::int64_t{16384} * (129 - (3 - neg) + e) - err;
  const std::int64_t room = std::min(top, bottom) - 1;  // reach <= room
  if (room < 0) return 0;
  return static_cast<int>(std::min<std::int64_t>(127, room / (len * 128)));
}
}  // namespace

bool cannot_wrap(const paper::packed_normal& p, int e, int s, const gs::model_options& o) noexcept {
  const std::int64_t len = isqrt_ceil(std::int64_t{p.iX} * p.iX + std::int64_t{p.iY} * p.iY + std::int64_t{p.iZ} * p.iZ);
  const std::int64_t l1 = std::abs(p.iX) + std::abs(p.iY) + std::abs(p.iZ);
  const int neg = (p.iX < 0) + (p.iY < 0) + (p.iZ < 0), nonneg = 3 - neg;
  // reach = (|n|·s·128 + |n|_1·E) / 16384, compared without division: value < reach + neg + e.
  const std::int64_t reach = len * s * 128 + l1 * max_error_units(o);
  return reach < std::int64_t{16384} * (128 - neg - e) && reach < std::int64_t{16384} * (129 - nonneg + e);
}

int bound_safe_s(const gs::model_options& o) {
  const two_pass::table t(o);
  int s = 127;
  for (const auto& p : appendix2_normals()) {
    const std::int64_t len = isqrt_ceil(std::int64_t{p.iX} * p.iX + std::int64_t{p.iY} * p.iY + std::int64_t{p.iZ} * p.iZ);
    const int neg = (p.iX < 0) + (p.iY < 0) + (p.iZ < 0);
    s = std::min(s, safe_s(len, std::abs(p.iX) + std::abs(p.iY) + std::abs(p.iZ), neg, t.alpha_error(p), o));
  }
  return s;
}

}  // namespace gsdot3::proofs::two_pass::triangle
