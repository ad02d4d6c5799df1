// valve/q23.hpp — exact arithmetic in the field Q(√2, √3): a + b√2 + c√3 + d√6 with rational
// a..d (64-bit numerators over one common denominator, reduced). Every component of the seed's
// bases lies in this field (√(2/3) = √6/3, 1/√2 = √2/2, 1/√3 = √3/3, 1/√6 = √6/6), so their dot
// products are decided exactly, without rounding.
#pragma once

#include <array>
#include <cstdint>
#include <numeric>

#include "valve/basis.hpp"

namespace gsdot3::valve {

struct q23 {
  std::array<std::int64_t, 4> n{};  // coefficients of 1, √2, √3, √6
  std::int64_t den = 1;             // > 0

  static constexpr q23 rational(std::int64_t num, std::int64_t d = 1) noexcept {
    return q23{{num, 0, 0, 0}, d}.reduced();
  }
  // (k/d)·√r for r ∈ {1, 2, 3, 6}.
  static constexpr q23 root(int r, std::int64_t k, std::int64_t d) noexcept {
    q23 q;
    q.n[r == 1 ? 0 : r == 2 ? 1 : r == 3 ? 2 : 3] = k;
    q.den = d;
    return q.reduced();
  }
  constexpr q23 reduced() const noexcept {
    q23 q = *this;
    if (q.den < 0) {
      q.den = -q.den;
      for (auto& v : q.n) v = -v;
    }
    std::int64_t g = q.den;
    for (auto v : q.n) g = std::gcd(g, v);
    if (g > 1) {
      q.den /= g;
      for (auto& v : q.n) v /= g;
    }
    return q;
  }
  friend constexpr q23 operator+(const q23& a, const q23& b) noexcept {
    q23 q;
    q.den = a.den * b.den;
    for (int i = 0; i < 4; ++i)
      q.n[static_cast<unsigned>(i)] = a.n[static_cast<unsigned>(i)] * b.den + b.n[static_cast<unsigned>(i)] * a.den;
    return q.reduced();
  }
  friend constexpr q23 operator-(const q23& a) noexcept {
    q23 q = a;
    for (auto& v : q.n) v = -v;
    return q;
  }
  friend constexpr q23 operator-(const q23& a, const q23& b) noexcept { return a + (-b); }
  // (a0 + a1√2 + a2√3 + a3√6)(b0 + b1√2 + b2√3 + b3√6), with √2√3 = √6, √2√6 = 2√3, √3√6 = 3√2.
  friend constexpr q23 operator*(const q23& a, const q23& b) noexcept {
    const auto& x = a.n;
    const auto& y = b.n;
    q23 q;
    q.den = a.den * b.den;
    q.n[0] = x[0] * y[0] + 2 * x[1] * y[1] + 3 * x[2] * y[2] + 6 * x[3] * y[3];
    q.n[1] = x[0] * y[1] + x[1] * y[0] + 3 * (x[2] * y[3] + x[3] * y[2]);
    q.n[2] = x[0] * y[2] + x[2] * y[0] + 2 * (x[1] * y[3] + x[3] * y[1]);
    q.n[3] = x[0] * y[3] + x[3] * y[0] + x[1] * y[2] + x[2] * y[1];
    return q.reduced();
  }
  friend constexpr bool operator==(const q23& a, const q23& b) noexcept {
    const q23 p = a.reduced(), q = b.reduced();
    return p.n == q.n && p.den == q.den;
  }
  constexpr double value() const noexcept {
    return (static_cast<double>(n[0]) + static_cast<double>(n[1]) * 1.4142135623730951 +
            static_cast<double>(n[2]) * 1.7320508075688772 + static_cast<double>(n[3]) * 2.4494897427831781) /
           static_cast<double>(den);
  }
};

using q23_basis = std::array<vec3<q23>, 3>;

// Source's bumpvects.h basis, exactly.
inline constexpr q23_basis exact_basis_q23 = {{
    {q23::root(6, 1, 3), q23::rational(0), q23::root(3, 1, 3)},
    {q23::root(6, -1, 6), q23::root(2, 1, 2), q23::root(3, 1, 3)},
    {q23::root(6, -1, 6), q23::root(2, -1, 2), q23::root(3, 1, 3)},
}};

// The seed's equation (1) as printed, exactly.
inline constexpr q23_basis printed_basis_q23 = {{
    {q23::root(6, -1, 6), q23::root(2, 1, 2), q23::root(3, 1, 3)},
    {q23::root(6, -1, 6), q23::root(2, 1, 2), q23::root(3, 1, 3)},
    {q23::root(6, -1, 3), q23::rational(0), q23::root(3, 1, 3)},
}};

}  // namespace gsdot3::valve
