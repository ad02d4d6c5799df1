#include "proofs/two_pass.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "proofs/methods.hpp"

namespace gsdot3::proofs::two_pass {

namespace m = methods;

palette_pair palettes(const paper::packed_normal& p) noexcept {
  return {{m::byte(p.R_pos), m::byte(p.G_pos), m::byte(p.B_pos), m::byte(0)},
          {m::byte(p.R_neg), m::byte(p.G_neg), m::byte(p.B_neg), m::byte(p.alpha)},
          {m::byte(128 + p.R_neg - p.R_pos), m::byte(128 + p.G_neg - p.G_pos), m::byte(128 + p.B_neg - p.B_pos),
           m::byte(0x80)}};
}

gs::fragment_colour vertex_light(const ivec3& l) noexcept {
  return gs::fragment_colour::flat({m::byte(128 + l[0]), m::byte(128 + l[1]), m::byte(128 + l[2]), m::byte(0x80)});
}

pixel_result pixel(const paper::packed_normal& p, gs::fragment_colour light, const gs::model_options& o,
                   na_term na) noexcept {
  const auto pal = palettes(p);
  const gs::rgba8 dpb1 = m::two_pass_pass1(pal.pos, light, o);
  const auto p2 = m::two_pass_pass2_wide(pal.neg, light, dpb1, o);
  const gs::rgba8 dpb2 = gs::colclamp(p2.wide, p2.as, false);
  const int products = p2.wide.r.value() + p2.wide.g.value() + p2.wide.b.value();
  if (na == na_term::thirds_in_alpha)
    return {products + 3 * p2.as.value() - 384, m::as_signed(m::minus_128(m::sum_rgb_plus_3a(dpb2, o), o))};
  const gs::rgb_wide p3 = m::three_pass_pass3_wide(pal.terms, dpb2, o);
  const int added = p3.r.value() - dpb2.r.value() + p3.g.value() - dpb2.g.value() + p3.b.value() - dpb2.b.value();
  const gs::rgba8 dpb3 = m::three_pass_pass3(pal.terms, dpb2, o);
  return {products + added - 384, m::as_signed(m::minus_128(m::sum_rgb(dpb3, o), o))};
}

table::table(const gs::model_options& o, na_term mode) : m_(mode), channel_(256 * 256), alpha_(256), term_(256) {
  for (int n = -127; n <= 128; ++n)
    for (int l = -128; l <= 127; ++l) {
      const auto light = gs::fragment_colour::flat(m::grey(128 + l, 0x80));
      const gs::rgba8 dpb1 = m::two_pass_pass1(m::grey(std::max(n, 0), 0), light, o);
      const auto p2 = m::two_pass_pass2_wide(m::grey(std::max(-n, 0), 0), light, dpb1, o);
      channel_[static_cast<std::size_t>((n + 127) * 256 + (l + 128))] = static_cast<std::int16_t>(p2.wide.r.value());
    }
  for (int a = 0; a < 256; ++a) {
    const auto light = gs::fragment_colour::flat(m::grey(0x80, 0x80));
    alpha_[static_cast<std::size_t>(a)] =
        static_cast<std::int16_t>(m::two_pass_pass2_wide(m::grey(0, a), light, m::grey(0, 0), o).as.value());
  }
  for (int n = -127; n <= 128; ++n)  // over a DPB byte of 0 (the blend adds Cd back unchanged)
    term_[static_cast<std::size_t>(n + 127)] =
        static_cast<std::int16_t>(m::three_pass_pass3_wide(m::grey(128 - n, 0x80), m::grey(0, 0), o).r.value());
}

light_grid::light_grid(int s_) : s(s_), lights(packed_lights(s_)) {
  const int side = 2 * s + 1;
  start.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side) + 1, 0);
  // lights are in (x, y, z) order: count per cell, then prefix sums.
  for (const auto& l : lights) ++start[cell(l[0], l[1]) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
}

namespace {
int sign_counts_neg(const paper::packed_normal& p) { return (p.iX < 0) + (p.iY < 0) + (p.iZ < 0); }

// Appends the indices of lights with d·l >= t (d = ±n) to `out`.
void cap(const light_grid& g, const ivec3& d, std::int64_t t, std::vector<std::uint32_t>& out) {
  const double len =
      std::sqrt(static_cast<double>(d[0]) * d[0] + static_cast<double>(d[1]) * d[1] + static_cast<double>(d[2]) * d[2]);
  const double h0 = static_cast<double>(t) / len;  // d̂·l >= h0 on the cap
  if (h0 > g.s + 1e-9) return;                     // |l| <= s: empty
  const double hmin = std::max(h0, -static_cast<double>(g.s));
  const double rho = std::sqrt(std::max(0.0, static_cast<double>(g.s) * g.s - (h0 > 0 ? h0 * h0 : 0.0)));
  auto range = [&](int c, int& lo, int& hi) {
    const double u = d[static_cast<std::size_t>(c)] / len;
    const double a = std::min(hmin * u, g.s * u), b = std::max(hmin * u, g.s * u);
    lo = std::max(-g.s, static_cast<int>(std::floor(a - rho)) - 1);
    hi = std::min(g.s, static_cast<int>(std::ceil(b + rho)) + 1);
  };
  int x0, x1, y0, y1;
  range(0, x0, x1);
  range(1, y0, y1);
  for (int x = x0; x <= x1; ++x)
    for (int y = y0; y <= y1; ++y)
      for (auto j = g.cell_begin(x, y); j < g.cell_end(x, y); ++j) {
        const auto& l = g.lights[j];
        if (std::int64_t{d[0]} * l[0] + std::int64_t{d[1]} * l[1] + std::int64_t{d[2]} * l[2] >= t) out.push_back(j);
      }
}
}  // namespace

wrap_hits wrap_search(const std::vector<paper::packed_normal>& normals, const light_grid& grid, const table& t, int hi,
                      int lo, const sweep_config& cfg) {
  const std::uint64_t nl = grid.lights.size();
  return sweep<wrap_hits>(normals.size(), cfg, [&](wrap_hits& acc, std::uint64_t b, std::uint64_t end) {
    std::vector<std::uint32_t> cand;
    for (auto i = b; i < end; ++i) {
      const auto& p = normals[i];
      const int e = t.alpha_error(p), neg = sign_counts_neg(p), nonneg = 3 - neg;
      const ivec3 n{p.iX, p.iY, p.iZ}, minus_n{-p.iX, -p.iY, -p.iZ};
      cand.clear();
      cap(grid, n, std::int64_t{128} * (hi - e) - 127 * neg, cand);
      cap(grid, minus_n, -(std::int64_t{128} * (lo - e) + 127 * nonneg), cand);
      std::sort(cand.begin(), cand.end());
      cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
      for (auto j : cand) {
        ++acc.evaluated;
        const int v = t.value(p, grid.lights[j]);
        if (v >= hi || v <= lo) acc.hits.add(i * nl + j);
      }
    }
  });
}

wrap_hits wrap_search_brute(const std::vector<paper::packed_normal>& normals, const light_grid& grid, const table& t,
                            int hi, int lo, const sweep_config& cfg) {
  const std::uint64_t nl = grid.lights.size();
  return sweep<wrap_hits>(normals.size(), cfg, [&](wrap_hits& acc, std::uint64_t b, std::uint64_t end) {
    for (auto i = b; i < end; ++i)
      for (std::uint64_t j = 0; j < nl; ++j) {
        ++acc.evaluated;
        const int v = t.value(normals[i], grid.lights[j]);
        if (v >= hi || v <= lo) acc.hits.add(i * nl + j);
      }
  });
}

namespace {
struct first_hit {
  std::uint64_t index = UINT64_MAX;
  std::uint64_t evaluated = 0;
  void merge(const first_hit& l) {
    index = std::min(index, l.index);
    evaluated += l.evaluated;
  }
};
// The first pair whose error equals `target`, among normals that pass `eligible`. A chunk stops at a
// normal past the best index found so far, so the minimum found is the minimum overall.
template <class Eligible>
first_hit find_error(const std::vector<paper::packed_normal>& normals, const light_grid& g, const table& t, int target,
                     Eligible eligible, const sweep_config& cfg) {
  const std::uint64_t nl = g.lights.size();
  std::atomic<std::uint64_t> best{UINT64_MAX};
  return sweep<first_hit>(normals.size(), cfg, [&](first_hit& acc, std::uint64_t b, std::uint64_t end) {
    for (auto i = b; i < end && i * nl < best.load(); ++i) {
      const auto& p = normals[i];
      if (!eligible(p)) continue;
      for (std::uint64_t j = 0; j < nl; ++j) {
        ++acc.evaluated;
        if (t.value(p, g.lights[j]) - exact_dot(p, g.lights[j]) == target) {
          acc.index = std::min(acc.index, i * nl + j);
          std::uint64_t cur = best.load();
          while (i * nl + j < cur && !best.compare_exchange_weak(cur, i * nl + j)) {}
          return;
        }
      }
    }
  });
}
}  // namespace

error_result error_extremes(const std::vector<paper::packed_normal>& normals, const light_grid& g, const table& t,
                            const sweep_config& cfg) {
  int e_min = 0, e_max = 0;
  if (!normals.empty()) e_min = e_max = t.alpha_error(normals.front());
  for (const auto& p : normals) e_min = std::min(e_min, t.alpha_error(p)), e_max = std::max(e_max, t.alpha_error(p));
  const auto hi = find_error(
      normals, g, t, e_max + 2,
      [&](const paper::packed_normal& p) { return t.alpha_error(p) == e_max && p.iX < 0 && p.iY < 0; }, cfg);
  const auto lo = find_error(
      normals, g, t, e_min - 2,
      [&](const paper::packed_normal& p) { return t.alpha_error(p) == e_min && p.iX >= 0 && p.iY >= 0; }, cfg);
  error_result r;
  r.evaluated = hi.evaluated + lo.evaluated;
  if (hi.index != UINT64_MAX && lo.index != UINT64_MAX) {
    r.err.add(e_max + 2, hi.index);
    r.err.add(e_min - 2, lo.index);
    return r;
  }
  struct acc {
    extremes e;
    void merge(const acc& l) { e.merge(l.e); }
  };
  const std::uint64_t nl = g.lights.size();
  r.full_scan = true;
  r.evaluated += normals.size() * nl;
  r.err = sweep<acc>(normals.size(), cfg, [&](acc& a, std::uint64_t b, std::uint64_t end) {
            for (auto i = b; i < end; ++i)
              for (std::uint64_t j = 0; j < nl; ++j)
                a.e.add(t.value(normals[i], g.lights[j]) - exact_dot(normals[i], g.lights[j]), i * nl + j);
          }).e;
  return r;
}

}  // namespace gsdot3::proofs::two_pass
