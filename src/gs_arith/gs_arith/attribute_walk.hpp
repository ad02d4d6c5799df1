// gs_arith/attribute_walk.hpp — a triangle's attributes stepped along a row of pixels: the fast path of
// triangle_attributes::colour_at and plane::at (attribute_setup.hpp, rasteriser.hpp), which stay the
// readable reference. At (x + 1, y) after (x, y) each value comes from the last one by additions; any
// other move starts again from the reference formulas. Equal to them at every pixel: each plane is
// linear in x along a row, so its numerator grows by a constant, and floor(n / d) with its remainder
// follows n exactly (floor_division_walk; an exact UV plane too, plane_walk); truncation toward zero is the floor plus
// one for a negative inexact quotient. Checked pixel for pixel against the reference on random triangles under every
// set-up (tests/gs_arith/attribute_walk_test.cpp) and on whole frames (pipeline_simd_frame: the SIMD
// path walks, --scalar does not).
// gouraud_setup::pcsx2_rows_4 / _8 (row-start dependent, not a plane) are evaluated at every pixel.
// A colour plane that does not change (every channel's x and y gradient numerators 0, as for equal
// vertex colours: the methods' white passes) is the same at every pixel: n = 0 under per_pixel,
// per_pixel_floor and per_pixel_level, base alone under plane_steps; it is computed where the walk starts and kept.
#pragma once

#include <array>
#include <cstdint>

#include "gs_arith/attribute_setup.hpp"
#include "gs_arith/gouraud.hpp"

namespace gs {

// floor(n / d) and n − d·floor(n / d) for n = n0 + k·s, d > 0, stepped in k without a division.
// The step's quotient and remainder are kept while the step and the divisor stay (a triangle's rows).
struct floor_division_walk {
  std::int64_t q = 0, r = 0, dq = 0, dr = 0, d = 0, s = 0;  // d = 0: never started
  constexpr void start(std::int64_t n0, std::int64_t step_n, std::int64_t den) noexcept {
    if (den != d || step_n != s) d = den, s = step_n, dq = floor_div(s, d), dr = s - dq * d;
    q = floor_div(n0, d), r = n0 - q * d;
  }
  // The carry as a value, not a branch: it follows the remainder, which no predictor follows.
  constexpr void step() noexcept {
    q += dq, r += dr;
    const std::int64_t carry = r >= d ? 1 : 0;
    q += carry, r -= d & -carry;
  }
  // trunc(n / d): the floor, plus one when n < 0 (q < 0) and d does not divide n.
  constexpr std::int64_t toward_zero() const noexcept { return q + (q < 0 && r != 0 ? 1 : 0); }
};

// plane::quotient along a row: the numerator n = base + dx·x + dy·y, and for an exact plane (den > 0)
// floor(n / den) with its remainder, stepped without a division.
struct plane_walk {
  std::int64_t n = 0;
  floor_division_walk w;
  constexpr void start(const plane& p, int x, int y) noexcept {
    n = p.base + p.dx * x + p.dy * y;
    if (p.den != 0) w.start(n, p.dx, p.den);
  }
  constexpr void step(const plane& p) noexcept {
    n += p.dx;
    if (p.den != 0) w.step();
  }
  constexpr std::int64_t value(const plane& p) const noexcept { return p.den == 0 ? n >> 16 : p.lifted(w.q, w.r); }
  // plane::at from the walked value.
  constexpr std::int32_t at(const plane& p) const noexcept {
    const std::int64_t v = value(p);
    return static_cast<std::int32_t>(v < p.lo ? p.lo : v > p.hi ? p.hi : v);
  }
};

// Whether a triangle's colour is one value over the whole plane (the header's reason).
constexpr bool flat_colour(const triangle_attributes& a) noexcept {
  if (a.setup == gouraud_setup::pcsx2_rows_4 || a.setup == gouraud_setup::pcsx2_rows_8) return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (a.setup == gouraud_setup::plane_steps ? a.colour.dx[i].value() != 0 || a.colour.dy[i].value() != 0
                                              : a.colour.exact.nx[i] != 0 || a.colour.exact.ny[i] != 0)
      return false;
  return true;
}

class attribute_walker {
 public:
  struct values {
    fragment_colour cf;
    std::int32_t u, v;
  };
  explicit constexpr attribute_walker(const triangle_attributes& a) noexcept : a_(a), flat_(flat_colour(a)) {}

  // The attributes at window pixel (x, y): colour_at(x, y), u.at(x, y), v.at(x, y).
  constexpr values at(int x, int y) noexcept {
    if (started_ && y == y_ && x == x_ + 1 && steppable(x)) {
      step();
    } else {
      start(x, y);
      if (flat_ && !started_) cf_ = colour(x, y);
      started_ = true;
    }
    x_ = x, y_ = y;
    return {flat_ ? cf_ : colour(x, y), u_.at(a_.u), v_.at(a_.v)};
  }

  // at(x0 + k, y) for k = 0 .. n − 1, in that order, as f(k, values): at()'s fast path for a run of a
  // row. Whether the run steps is decided once from its ends (the pixel distance steppable() bounds is
  // monotone in x, so its range holds between two pixels that satisfy it), and u, v skip their clamp
  // when both ends of the run are inside the plane's [lo, hi] (acc >> 16 is monotone in k too).
  template <class F>
  constexpr void row(int x0, int y, int n, F&& f) noexcept(noexcept(f(0, values{}))) {
    if (n <= 0) return;
    f(0, at(x0, y));
    if (n > 1 && !(steppable(x0 + 1) && steppable(x0 + n - 1))) {
      for (int k = 1; k < n; ++k) f(k, at(x0 + k, y));
      return;
    }
    const bool inside = unclamped(a_.u, u_, n - 1) && unclamped(a_.v, v_, n - 1);
    for (int k = 1; k < n; ++k) {
      step();
      const std::int32_t u = inside ? static_cast<std::int32_t>(u_.value(a_.u)) : u_.at(a_.u);
      const std::int32_t v = inside ? static_cast<std::int32_t>(v_.value(a_.v)) : v_.at(a_.v);
      f(k, values{flat_ ? cf_ : colour(x0 + k, y), u, v});
    }
    x_ = x0 + n - 1;
  }

 private:
  // clamp_distance(k + 1) = clamp_distance(k) + 1 for the plane's pixel distance k (gouraud.hpp).
  constexpr bool steppable(int x) const noexcept {
    const std::int64_t k = a_.setup == gouraud_setup::plane_steps ? std::int64_t{x} + a_.offset_x - a_.colour.x_ref
                                                                  : std::int64_t{x} + a_.offset_x;
    return k > -65536 && k <= 65536;
  }
  constexpr void start(int x, int y) noexcept {
    u_.start(a_.u, x, y);
    v_.start(a_.v, x, y);
    const gouraud_plane& p = a_.colour;
    const gouraud_exact_plane& e = p.exact;
    const std::int64_t xo = std::int64_t{x} + a_.offset_x, yo = std::int64_t{y} + a_.offset_y;
    const std::int64_t px = clamp_distance(xo) * 16 - e.x0, py = clamp_distance(yo) * 16 - e.y0;
    const std::int64_t sign = e.det < 0 ? -1 : 1;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::int64_t n = (e.nx[i] * px + e.ny[i] * py) * 128, s = e.nx[i] * 2048;
      switch (a_.setup) {
        case gouraud_setup::plane_steps:
          units_[i] = p.base[i].value() + clamp_distance(xo - p.x_ref) * p.dx[i].value() +
                      clamp_distance(yo - p.y_ref) * p.dy[i].value();
          break;
        case gouraud_setup::per_pixel:
        case gouraud_setup::per_pixel_floor: walk_[i].start(sign * n, sign * s, sign * e.det); break;
        case gouraud_setup::per_pixel_level: {
          const std::int64_t num = sign * (e.c0[i].value() * e.det + n), den = sign * e.det;
          walk_[i].start(2 * num + den, 2 * sign * s, 256 * den);
          break;
        }
        case gouraud_setup::pcsx2_rows_4:
        case gouraud_setup::pcsx2_rows_8: break;
      }
    }
  }
  constexpr void step() noexcept {
    u_.step(a_.u), v_.step(a_.v);
    if (flat_) return;
    for (std::size_t i = 0; i < 4; ++i) {
      if (a_.setup == gouraud_setup::plane_steps) {
        units_[i] += a_.colour.dx[i].value();
      } else {
        walk_[i].step();
      }
    }
  }
  constexpr fragment_colour colour(int x, int y) const noexcept {
    std::array<gouraud_channel, 4> c{};
    for (std::size_t i = 0; i < 4; ++i) {
      switch (a_.setup) {
        case gouraud_setup::plane_steps: c[i] = gouraud_channel::from_saturated(units_[i]); break;
        case gouraud_setup::per_pixel:
          c[i] = gouraud_channel::from_saturated(a_.colour.exact.c0[i].value() + walk_[i].toward_zero());
          break;
        case gouraud_setup::per_pixel_floor:  // c0 is whole: c0 + floor(n / d) = floor(c0 + n / d)
          c[i] = gouraud_channel::from_saturated(a_.colour.exact.c0[i].value() + walk_[i].q);
          break;
        case gouraud_setup::per_pixel_level: c[i] = gouraud_channel::from_saturated(128 * walk_[i].q); break;
        case gouraud_setup::pcsx2_rows_4:
        case gouraud_setup::pcsx2_rows_8: return a_.colour_at(x, y);
      }
    }
    return {c[0], c[1], c[2], c[3]};
  }
  // Whether the value here and `steps` pixels on both lie in [lo, hi] (then every step between does). An
  // exact plane's value k pixels on is q + k·dq + floor((r + k·dr) / den), with 0 <= r, dr < den: within
  // [q + k·dq, q + k·dq + k] (+ 1 lifted), a bound without a division; a run whose bound reaches past
  // the clamp takes the clamped path, exact either way.
  static constexpr bool unclamped(const plane& p, const plane_walk& w, int steps) noexcept {
    const std::int64_t first = w.value(p);
    const std::int64_t low = p.den == 0 ? (w.n + p.dx * steps) >> 16 : w.w.q + w.w.dq * steps;
    const std::int64_t high = p.den == 0 ? low : low + steps + 1;
    return first >= p.lo && first <= p.hi && low >= p.lo && high <= p.hi;
  }

  const triangle_attributes& a_;
  bool flat_;
  fragment_colour cf_{};  // the colour of a flat plane
  int x_ = 0, y_ = 0;
  bool started_ = false;
  plane_walk u_, v_;
  std::array<std::int64_t, 4> units_{};
  std::array<floor_division_walk, 4> walk_{};
};

}  // namespace gs
