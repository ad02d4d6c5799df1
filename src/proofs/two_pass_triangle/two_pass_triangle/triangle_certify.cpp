#include "two_pass_triangle/triangle_certify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "two_pass_triangle/damped_newton.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"

namespace gsdot3::proofs::two_pass::triangle::certify {

namespace {
__extension__ typedef __int128 i128;  // exact products of 2^-24 duals and 2^-20 coordinates
__extension__ typedef unsigned __int128 u128;

// The ceiling of the square root of v (v < 2^126).
u128 sqrt_ceil(u128 v) {
  auto r = static_cast<u128>(std::sqrt(static_cast<long double>(v)));
  while (r * r < v) ++r;
  while (r > 0 && (r - 1) * (r - 1) >= v) --r;
  return r;
}

bool charged(unsigned pattern, int c, int ax) { return (pattern >> (2 * c + ax) & 1) != 0; }

// The two vertices other than p.
std::array<int, 2> others(int p) { return {(p + 1) % 3, (p + 2) % 3}; }

// The search works on x[c][i] = y_{k_i, c} (k_0, k_1 the vertices other than p); y_p = w − x_0 − x_1.
// Row (c, corner, ax): n·x_c >= 0 with n = ±(p_ax − X_{k_0, ax}, p_ax − X_{k_1, ax}) (+ charged:
// κ >= 0, − uncharged: κ <= 0), normalised.
struct row {
  int c;
  double n0, n1;
};
struct lag_term {  // a charged (c, ax) at one corner: m = w_c·p_ax − d0·x_{c,0} − d1·x_{c,1} (levels·|n|·128)
  int c, j;
  double wp, d0, d1;
};

struct smoothed {
  const problem& pr;
  int corner_count;
  std::vector<row> rows;
  std::vector<lag_term> lags;
  std::array<bool, 3> free{};
  double mu = 1, tau = 1, eps = 1, T = 1;

  // Value; with grad and hess when asked. Returns +inf outside the barrier's domain.
  double eval(const double* x, double* g, double* H) const {
    if (g) std::fill(g, g + 6, 0.0), std::fill(H, H + 36, 0.0);
    double f = 0;
    for (const auto& r : rows) {
      const double q = r.n0 * x[2 * r.c] + r.n1 * x[2 * r.c + 1];
      if (!(q > 0)) return INFINITY;
      f -= mu * std::log(q);
      if (g) {
        const double n[2] = {r.n0, r.n1};
        for (int i = 0; i < 2; ++i) {
          g[2 * r.c + i] -= mu * n[i] / q;
          for (int k = 0; k < 2; ++k) H[(2 * r.c + i) * 6 + 2 * r.c + k] += mu * n[i] * n[k] / (q * q);
        }
      }
    }
    // s·Σ_k sqrt(|y_k|² + ε²): vertex i = 0, 1 (coefficient +1 on x[c][i]) and p (−1 on both).
    for (int v = 0; v < 3; ++v) {
      double y[3], coef[3][2];
      for (int c = 0; c < 3; ++c) {
        if (v < 2)
          y[c] = x[2 * c + v], coef[c][0] = v == 0, coef[c][1] = v == 1;
        else
          y[c] = pr.w[c] - x[2 * c] - x[2 * c + 1], coef[c][0] = coef[c][1] = -1;
      }
      const double N = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + eps * eps);
      f += pr.s * N;
      if (g)
        for (int c = 0; c < 3; ++c)
          for (int i = 0; i < 2; ++i) {
            g[2 * c + i] += pr.s * coef[c][i] * y[c] / N;
            for (int c2 = 0; c2 < 3; ++c2)
              for (int i2 = 0; i2 < 2; ++i2)
                H[(2 * c + i) * 6 + 2 * c2 + i2] +=
                    pr.s * coef[c][i] * coef[c2][i2] * ((c == c2) / N - y[c] * y[c2] / (N * N * N));
          }
    }
    // T·log Σ_j exp(S_j/T), S_j = Σ softplus_τ(m/128) over the charged axes at corner j.
    double S[4] = {0, 0, 0, 0}, gS[4][6] = {}, HS[4][36] = {};
    for (const auto& l : lags) {
      const double m = (l.wp - l.d0 * x[2 * l.c] - l.d1 * x[2 * l.c + 1]) / 128, z = m / tau;
      S[l.j] += z > 0 ? m + tau * std::log1p(std::exp(-z)) : tau * std::log1p(std::exp(z));
      if (g) {
        const double sg = 1 / (1 + std::exp(-z)), h = sg * (1 - sg) / tau;
        const double d[2] = {-l.d0 / 128, -l.d1 / 128};
        for (int i = 0; i < 2; ++i) {
          gS[l.j][2 * l.c + i] += sg * d[i];
          for (int k = 0; k < 2; ++k) HS[l.j][(2 * l.c + i) * 6 + 2 * l.c + k] += h * d[i] * d[k];
        }
      }
    }
    const double top = *std::max_element(S, S + corner_count);
    double Z = 0, pi[4];
    for (int j = 0; j < corner_count; ++j) Z += pi[j] = std::exp((S[j] - top) / T);
    f += top + T * std::log(Z);
    if (g) {
      double gl[6] = {};
      for (int j = 0; j < corner_count; ++j) {
        pi[j] /= Z;
        for (int a = 0; a < 6; ++a) gl[a] += pi[j] * gS[j][a];
      }
      for (int a = 0; a < 6; ++a) {
        g[a] += gl[a];
        for (int b = 0; b < 6; ++b) {
          double h = -gl[a] * gl[b] / T;
          for (int j = 0; j < corner_count; ++j) h += pi[j] * (HS[j][a * 6 + b] + gS[j][a] * gS[j][b] / T);
          H[a * 6 + b] += h;
        }
      }
    }
    return f;
  }
};

// A direction inside the cone {x: n·x >= 0 for every row of channel c}, or false if the cone has an
// empty interior (then x_c stays 0).
bool interior_direction(const std::vector<row>& rows, int c, double dir[2]) {
  std::vector<std::array<double, 2>> cand, normals;
  for (const auto& r : rows)
    if (r.c == c) normals.push_back({r.n0, r.n1}), cand.push_back({-r.n1, r.n0}), cand.push_back({r.n1, -r.n0});
  if (normals.empty()) return false;
  std::vector<std::array<double, 2>> ok;
  for (const auto& e : cand)
    if (std::all_of(normals.begin(), normals.end(), [&](const auto& n) { return n[0] * e[0] + n[1] * e[1] >= -1e-12; }))
      ok.push_back(e);
  double best = -2;
  std::array<double, 2> e1{}, e2{};
  for (const auto& a : ok)
    for (const auto& b : ok)
      if (const double cs = a[0] * b[0] + a[1] * b[1]; - cs > best) best = -cs, e1 = a, e2 = b;  // the widest pair
  if (ok.empty() || best < -1 + 1e-12) return false;                                             // a ray or nothing
  if (best > 1 - 1e-12) {  // a half-plane: every row parallel
    dir[0] = normals[0][0], dir[1] = normals[0][1];
    return true;
  }
  const double sx = e1[0] + e2[0], sy = e1[1] + e2[1], l = std::hypot(sx, sy);
  dir[0] = sx / l, dir[1] = sy / l;
  return true;
}

double px(std::int64_t v) { return static_cast<double>(v) / coord_one; }
}  // namespace

vertices family_member(int family, std::int64_t u, std::int64_t v, std::int64_t box) {
  const std::int64_t A = box * coord_one;
  switch (family) {
    case 0: return {{{0, u}, {v, 0}, {A, A}}};
    case 1: return {{{0, u}, {A, 0}, {v, A}}};
    case 2: return {{{0, 0}, {A, u}, {v, A}}};
    case 3: return {{{0, 0}, {A, A}, {u, v}}};
    default: return {{{0, A}, {A, 0}, {u, v}}};
  }
}

corners family_cell(int family, int p, std::int64_t u0, std::int64_t u1, std::int64_t v0, std::int64_t v1,
                    std::int64_t box) {
  return {{family_member(family, u0, v0, box), family_member(family, u1, v0, box), family_member(family, u0, v1, box),
           family_member(family, u1, v1, box)},
          p};
}

std::vector<unsigned> patterns(const problem& pr) {
  std::vector<unsigned> out;
  for (unsigned pi = 0; pi < 64; ++pi) {
    bool keep = true;
    for (int c = 0; c < 3; ++c)
      if (pr.w[c] == 0 && (pi >> (2 * c) & 3) != 0) keep = false;
    if (keep) out.push_back(pi);
  }
  return out;
}

dual_real search_dual(const problem& pr, const corners& g, unsigned pattern, const dual_real* warm) {
  const auto k = others(g.p);
  smoothed F{pr, static_cast<int>(g.at.size()), {}, {}, {}};
  for (int j = 0; j < F.corner_count; ++j) {
    const auto& V = g.at[static_cast<std::size_t>(j)];
    for (int ax = 0; ax < 2; ++ax) {
      const double p = px(V[g.p][ax]), d0 = p - px(V[k[0]][ax]), d1 = p - px(V[k[1]][ax]);
      for (int c = 0; c < 3; ++c) {
        if (pr.w[c] == 0) continue;
        const double sg = charged(pattern, c, ax) ? 1 : -1, l = std::hypot(d0, d1);
        if (l > 1e-9) F.rows.push_back({c, sg * d0 / l, sg * d1 / l});
        if (charged(pattern, c, ax)) F.lags.push_back({c, j, pr.w[c] * p, d0, d1});
      }
    }
  }
  double x[6] = {};
  for (int c = 0; c < 3; ++c) {
    double dir[2];
    F.free[c] = pr.w[c] != 0 && interior_direction(F.rows, c, dir);
    if (!F.free[c]) continue;
    double q_warm = 0;
    if (warm) {
      x[2 * c] = (*warm)[k[0]][c], x[2 * c + 1] = (*warm)[k[1]][c];
      q_warm = INFINITY;
      for (const auto& r : F.rows)
        if (r.c == c) q_warm = std::min(q_warm, r.n0 * x[2 * c] + r.n1 * x[2 * c + 1]);
    }
    if (!(q_warm > 1e-7)) {  // not strictly inside: step into the cone
      const double step = 1e-3 * pr.w[c] + 1e-3;
      x[2 * c] += step * dir[0], x[2 * c + 1] += step * dir[1];
    }
  }
  // Drop the rows of fixed channels (x_c = 0 there).
  std::erase_if(F.rows, [&](const row& r) { return !F.free[r.c]; });
  for (double scale = warm ? 1e-3 : 1; scale > 1e-6; scale *= 0.1) {
    F.mu = 10 * scale, F.tau = 10 * scale, F.T = 10 * scale, F.eps = scale;
    double f = F.eval(x, nullptr, nullptr);
    if (!std::isfinite(f)) break;
    for (int it = 0; it < 40; ++it) {
      double gr[6], H[36], d[6];
      F.eval(x, gr, H);
      if (!newton_step(F.free, H, gr, d)) break;
      double slope = 0;
      for (int a = 0; a < 6; ++a) slope += gr[a] * d[a];
      if (-slope < 1e-9 * F.mu) break;  // the Newton decrement: converged for this stage
      double alpha = 1, xn[6], fn = INFINITY;
      for (int h = 0; h < 50; ++h, alpha *= 0.5) {
        for (int a = 0; a < 6; ++a) xn[a] = x[a] + alpha * d[a];
        fn = F.eval(xn, nullptr, nullptr);
        if (fn <= f + 1e-4 * alpha * slope) break;
      }
      if (!(fn <= f)) break;
      std::copy(xn, xn + 6, x), f = fn;
    }
  }
  dual_real y{};
  for (int c = 0; c < 3; ++c) {
    y[k[0]][c] = x[2 * c], y[k[1]][c] = x[2 * c + 1];
    y[g.p][c] = pr.w[c] - x[2 * c] - x[2 * c + 1];
  }
  return y;
}

dual_grid to_grid(const problem& pr, const dual_real& y, int p) {
  const auto k = others(p);
  dual_grid Y{};
  for (int c = 0; c < 3; ++c) {
    const std::int64_t W = std::int64_t{pr.w[c]} << dual_bits;
    if (pr.w[c] == 0) continue;
    for (int i : k) {
      const double v = std::ldexp(y[static_cast<std::size_t>(i)][c], dual_bits);
      Y[static_cast<std::size_t>(i)][c] = std::fabs(v) < 0x1p50 ? std::llround(v) : 0;
    }
    Y[p][c] = W - Y[k[0]][c] - Y[k[1]][c];
  }
  return Y;
}

check check_dual(const problem& pr, const corners& g, unsigned pattern, const dual_grid& y) {
  check out;
  for (int c = 0; c < 3; ++c) {
    const std::int64_t sum = y[0][c] + y[1][c] + y[2][c];
    if (sum != (std::int64_t{pr.w[c]} << dual_bits)) return out;  // not a dual point
    if (pr.w[c] == 0 && (y[0][c] | y[1][c] | y[2][c]) != 0) return out;
  }
  i128 lag = 0;  // max over the corners of Σ_charged max(0, m), scaled by 2^(dual_bits + coord_bits)
  for (const auto& V : g.at) {
    i128 corner = 0;
    for (int c = 0; c < 3; ++c)
      for (int ax = 0; ax < 2; ++ax) {
        i128 m = 0;
        for (std::size_t k = 0; k < 3; ++k) m += i128{y[k][c]} * V[k][ax];
        const i128 kappa = (i128{pr.w[c]} << dual_bits) * V[g.p][ax] - m;
        if (charged(pattern, c, ax) ? kappa < 0 : kappa > 0) return out;
        if (charged(pattern, c, ax) && m > 0) corner += m;
      }
    lag = std::max(lag, corner);
  }
  u128 norms = 0;  // Σ_k ceil |Y_k|
  for (const auto& yk : y) {
    u128 n2 = 0;
    for (std::int64_t v : yk) n2 += static_cast<u128>(i128{v} * v);
    norms += sqrt_ceil(n2);
  }
  const i128 bound = i128{pr.s} * 128 * coord_one * static_cast<i128>(norms) + lag;
  out.feasible = true;
  out.below = bound < (i128{pr.threshold128} << (dual_bits + coord_bits));
  out.levels = std::ldexp(static_cast<long double>(bound), -(dual_bits + coord_bits + 7));
  return out;
}

double attained(const problem& pr, const std::array<std::array<double, 2>, 3>& v, int p, const dual_real& y) {
  relaxation_point x{};
  x.vertex = v;
  x.pixel = v[static_cast<std::size_t>(p)];
  for (std::size_t k = 0; k < 3; ++k) {
    const double n = std::sqrt(y[k][0] * y[k][0] + y[k][1] * y[k][1] + y[k][2] * y[k][2]);
    for (std::size_t c = 0; c < 3; ++c) x.light[k][c] = n > 0 ? pr.s * y[k][c] / n : 0;
  }
  return relaxation_value(x, {double(pr.w[0]), double(pr.w[1]), double(pr.w[2])}, pr.s);
}

outcome certify_class(const problem& pr, std::int64_t box, std::int64_t min_cell, std::int64_t max_cells,
                      std::size_t max_open, std::vector<closed_cell>* record) {
  outcome out;
  struct pending {
    std::int64_t u0, u1, v0, v1;
    dual_real warm;
    bool has_warm;
  };
  const std::int64_t A = box * coord_one;
  for (int f = 0; f < family_count; ++f)
    for (int p = 0; p < 3; ++p)
      for (unsigned pi : patterns(pr)) {
        // y_p = w: s·|w| plus every charged axis lagged in full, feasible everywhere; it closes the
        // patterns with few charged axes without a search.
        dual_real t{};
        for (int ch = 0; ch < 3; ++ch)
          t[static_cast<std::size_t>(p)][static_cast<std::size_t>(ch)] = pr.w[static_cast<std::size_t>(ch)];
        const dual_grid trivial = to_grid(pr, t, p);
        std::vector<pending> stack{{0, A, 0, A, {}, false}};
        while (!stack.empty()) {
          const pending c = stack.back();
          stack.pop_back();
          if (++out.cells > max_cells) return out.open_count += 1, out;
          const corners g = family_cell(f, p, c.u0, c.u1, c.v0, c.v1, box);
          auto close = [&](const check& k, const dual_grid& Y) {
            ++out.closed, out.worst_closed = std::max(out.worst_closed, k.levels);
            if (record) record->push_back({f, p, pi, c.u0, c.u1, c.v0, c.v1, Y});
          };
          if (const check k = check_dual(pr, g, pi, trivial); k.below) {  // no search needed
            close(k, trivial);
            continue;
          }
          const dual_real y = search_dual(pr, g, pi, c.has_warm ? &c.warm : nullptr);
          const dual_grid Y = to_grid(pr, y, p);
          const check k = check_dual(pr, g, pi, Y);
          if (k.feasible && k.below) {
            close(k, Y);
            continue;
          }
          if (c.u1 - c.u0 <= min_cell && c.v1 - c.v0 <= min_cell) {
            const auto V = family_member(f, (c.u0 + c.u1) / 2, (c.v0 + c.v1) / 2, box);
            std::array<std::array<double, 2>, 3> v{};
            for (std::size_t q = 0; q < 3; ++q) v[q] = {px(V[q][0]), px(V[q][1])};
            const double a = attained(pr, v, p, y);
            ++out.open_count, out.best_attained = std::max(out.best_attained, a);
            if (out.open.size() < max_open)
              out.open.push_back({f, p, pi, c.u0, c.u1, c.v0, c.v1, k.feasible ? k.levels : -1, a, y});
            if (a * 128 >
                static_cast<double>(pr.threshold128)) {  // the relaxation itself exceeds: no certificate exists
              out.exceeds = true, out.witness = {f, p, pi, c.u0, c.u1, c.v0, c.v1, k.feasible ? k.levels : -1, a, y};
              return out;
            }
            continue;
          }
          const std::int64_t um = (c.u0 + c.u1) / 2, vm = (c.v0 + c.v1) / 2;
          for (const auto& [a0, a1, b0, b1] :
               {std::array{c.u0, um, c.v0, vm}, {um, c.u1, c.v0, vm}, {c.u0, um, vm, c.v1}, {um, c.u1, vm, c.v1}})
            stack.push_back({a0, a1, b0, b1, y, true});
        }
      }
  return out;
}

}  // namespace gsdot3::proofs::two_pass::triangle::certify
