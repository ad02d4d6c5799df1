#include "two_pass_triangle/triangle_brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "gs_arith/gouraud.hpp"

namespace gsdot3::proofs::two_pass::triangle {

namespace {
bool not_both(const channel_view& v) { return !(v.aligned_x && v.aligned_y); }
bool both(const channel_view& v) { return v.aligned_x && v.aligned_y; }

constexpr channel_statement statement_table[statement_count] = {
    {"A", "sigma*L_c(p) < sigma*P_c(p) + W (aligned on at most one axis)", not_both,
     [](const channel_view& v, std::int64_t W) {
       return std::array<std::int64_t, 2>{v.sigma * (v.L * v.den_p - v.P_p), W * v.den_p};
     }},
    {"B", "sigma*L_c(p) < sigma*P_c(p) + 1 + a + b (aligned on both axes)", both,
     [](const channel_view& v, std::int64_t) {
       return std::array<std::int64_t, 2>{v.sigma * (v.L * v.den_p - v.P_p), (1 + v.a + v.b) * v.den_p};
     }},
    {"C", "sigma*L_c(p) < sigma*P_c(w) + W (aligned on both axes, w of point_w)", both,
     [](const channel_view& v, std::int64_t W) {
       return std::array<std::int64_t, 2>{v.sigma * (v.L * v.den_w - v.P_w), W * v.den_w};
     }},
};

// A case set up once: the edge vectors from vertex 0 (1/16 pixel), the GS plane, the vertex
// values, the gradient signs and the edge of w.
struct case_setup {
  std::array<std::int64_t, 6> xy16;
  std::int64_t x0, y0, ax, ay, bx, by, sign, adet;
  int xmax, ymax;
  lag_edge edge;
  gs::gouraud_plane plane;
  std::int64_t value[3][3];  // [vertex][channel] 128·(128 + l)
  bool aligned[3][2][2];     // [channel][σ = +1, −1][x, y]
  bool any_both;
};

std::optional<case_setup> set_up(const triangle_case& c) {
  case_setup s{};
  for (std::size_t k = 0; k < 6; ++k) s.xy16[k] = c.xy16[k];
  s.x0 = c.xy16[0], s.y0 = c.xy16[1];
  s.ax = c.xy16[2] - s.x0, s.ay = c.xy16[3] - s.y0, s.bx = c.xy16[4] - s.x0, s.by = c.xy16[5] - s.y0;
  const std::int64_t det = s.ax * s.by - s.bx * s.ay;
  if (det == 0) return std::nullopt;
  s.sign = det > 0 ? 1 : -1, s.adet = det * s.sign;
  s.edge = lag_edge_of(c.xy16);
  s.xmax = std::max({c.xy16[0], c.xy16[2], c.xy16[4]}) >> 4, s.ymax = std::max({c.xy16[1], c.xy16[3], c.xy16[5]}) >> 4;
  std::array<gs::gouraud_vertex, 3> v{};
  for (std::size_t k = 0; k < 3; ++k)
    v[k] = {c.xy16[2 * k] + xy_offset_pixels * 16, c.xy16[2 * k + 1] + xy_offset_pixels * 16, light_colour(c.light[k])};
  s.plane = *gs::gouraud_triangle(v[0], v[1], v[2], s.edge.rx + xy_offset_pixels, s.edge.ry + xy_offset_pixels);
  s.any_both = false;
  for (std::size_t ch = 0; ch < 3; ++ch) {
    for (std::size_t k = 0; k < 3; ++k) s.value[k][ch] = 128 * (128 + c.light[k][ch]);
    const std::int64_t d1 = c.light[1][ch] - c.light[0][ch], d2 = c.light[2][ch] - c.light[0][ch];
    const std::int64_t gx = (d1 * s.by - d2 * s.ay) * s.sign,
                       gy = (d2 * s.ax - d1 * s.bx) * s.sign;  // the exact gradient ×|det|/128
    for (int side = 0; side < 2; ++side) {
      const std::int64_t sigma = side == 0 ? 1 : -1;
      s.aligned[ch][side][0] = sigma * gx < 0, s.aligned[ch][side][1] = sigma * gy < 0;
      s.any_both = s.any_both || (sigma * gx < 0 && sigma * gy < 0);
    }
  }
  return s;
}

// Barycentric numerators (×|det|·scale) of the point q·(1/16 pixel)/scale: in the closed triangle
// iff u, v >= 0 and u + v <= |det|·scale.
bool in_closed_triangle(const case_setup& s, std::int64_t qx, std::int64_t qy, std::int64_t scale) {
  qx -= s.x0 * scale, qy -= s.y0 * scale;
  const std::int64_t u = (s.by * qx - s.bx * qy) * s.sign, v = (s.ax * qy - s.ay * qx) * s.sign;
  return u >= 0 && v >= 0 && u + v <= s.adet * scale;
}

// Every statement at pixel (x, y) (in the closed triangle): f(k, channel, view, {left, allowance}) for
// each statement k that applies; returns whether w is in the closed triangle.
template <class F>
bool visit_pixel(const case_setup& s, int x, int y, std::int64_t window, F&& f) {
  const auto L = gs::gouraud_at(s.plane, x + xy_offset_pixels, y + xy_offset_pixels);
  const std::int64_t light[3] = {L.r.value(), L.g.value(), L.b.value()};
  const std::int64_t qx = 16 * std::int64_t{x} - s.x0, qy = 16 * std::int64_t{y} - s.y0;
  const std::int64_t u = (s.by * qx - s.bx * qy) * s.sign, v = (s.ax * qy - s.ay * qx) * s.sign;
  const plane_point w = s.any_both ? point_w(s.edge, x, y) : plane_point{};
  bool w_inside = true;
  if (!w.at_pixel()) {  // w·16·den, from the vertices' own coordinates
    const std::size_t X = 2 * s.edge.X, Y = 2 * s.edge.Y;
    w_inside = in_closed_triangle(s, s.xy16[X] * (w.den - w.num) + s.xy16[Y] * w.num,
                                  s.xy16[X + 1] * (w.den - w.num) + s.xy16[Y + 1] * w.num, w.den);
  }
  channel_view view;
  view.a = x - s.edge.rx, view.b = y - s.edge.ry;
  view.den_p = s.adet;
  for (std::size_t ch = 0; ch < 3; ++ch) {
    view.L = light[ch];
    view.P_p = s.value[0][ch] * s.adet + (s.value[1][ch] - s.value[0][ch]) * u + (s.value[2][ch] - s.value[0][ch]) * v;
    if (w.at_pixel()) {
      view.P_w = view.P_p, view.den_w = view.den_p;
    } else {
      view.P_w = (w.den - w.num) * s.value[s.edge.X][ch] + w.num * s.value[s.edge.Y][ch], view.den_w = w.den;
    }
    for (int side = 0; side < 2; ++side) {
      view.sigma = side == 0 ? 1 : -1;
      view.aligned_x = s.aligned[ch][side][0], view.aligned_y = s.aligned[ch][side][1];
      // each row by its constant index, so that its two functions are called directly (inlined)
      [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((statement_table[K].applies(view) ? f(K, ch, view, statement_table[K].sides(view, window)) : void()), ...);
      }
      (std::make_index_sequence<statement_count>{});
    }
  }
  return w_inside;
}
}  // namespace

std::span<const channel_statement, statement_count> channel_statements() noexcept { return statement_table; }

void check_case(const triangle_case& c, std::uint64_t index, int window, brute_force_acc& acc) {
  const auto s = set_up(c);
  if (!s) return;  // zero area: covers nothing
  for (int y = s->edge.ry; y <= s->ymax; ++y)
    for (int x = s->edge.rx; x <= s->xmax; ++x) {
      if (!in_closed_triangle(*s, 16 * std::int64_t{x}, 16 * std::int64_t{y}, 1)) continue;
      ++acc.pixels;
      const std::uint64_t at = pixel_witness(index, x, y);
      bool broken[statement_count] = {};
      const bool w_inside = visit_pixel(
          *s, x, y, window, [&](std::size_t k, std::size_t, const channel_view&, std::array<std::int64_t, 2> sides) {
            const std::int64_t left = sides[0], allowance = sides[1];
            auto& st = acc.statement[k];
            ++st.checked;
            broken[k] = broken[k] || left >= allowance;
            // the ratio only where it may raise the maximum (the division is the loop's dearest step)
            if (st.ratio_ppm.empty() || static_cast<double>(left) * 1e6 >=
                                            static_cast<double>(st.ratio_ppm.max - 1) * static_cast<double>(allowance))
              st.ratio_ppm.add(static_cast<std::int64_t>(
                                   std::floor(static_cast<double>(left) / static_cast<double>(allowance) * 1e6)),
                               at);
          });
      for (std::size_t k = 0; k < statement_count; ++k)
        if (broken[k]) acc.statement[k].violations.add(at);
      if (!w_inside) acc.w_outside.add(at);
    }
}

std::string failures_at(const triangle_case& c, int window) {
  const auto s = set_up(c);
  if (!s || !in_closed_triangle(*s, 16 * std::int64_t{c.px}, 16 * std::int64_t{c.py}, 1))
    return "pixel not in the closed triangle";
  std::string out;
  const bool w_inside = visit_pixel(
      *s, c.px, c.py, window,
      [&](std::size_t k, std::size_t ch, const channel_view& v, std::array<std::int64_t, 2> sides) {
        if (sides[0] < sides[1]) return;
        char light[32];
        std::snprintf(light, sizeof light, "0x%04llx", static_cast<unsigned long long>(v.L));
        out += std::string(out.empty() ? "(" : "; (") + std::string(statement_table[k].name) + ") " +
               std::string(statement_table[k].text) + " fails on channel " + "rgb"[ch] + ", sigma " +
               std::to_string(v.sigma) + ": L_c " + light + ", P_c(p) = " + std::to_string(v.P_p) + "/" +
               std::to_string(v.den_p) + ", P_c(w) = " + std::to_string(v.P_w) + "/" + std::to_string(v.den_w) +
               ", left " + std::to_string(sides[0]) + " >= allowance " + std::to_string(sides[1]);
      });
  if (!w_inside) out += (out.empty() ? "" : "; ") + std::string("w is outside the closed triangle");
  return out;
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

brute_force_acc brute_force(const sweep_config& cfg, std::uint64_t first, std::uint64_t count) {
  return sweep<brute_force_acc>(
      count, cfg,
      [first](brute_force_acc& acc, std::uint64_t begin, std::uint64_t end) {
        for (std::uint64_t i = first + begin; i < first + end; ++i)
          check_case(brute_force_case(i), i, window_pixels, acc);
      },
      std::uint64_t{1} << 16);
}

}  // namespace gsdot3::proofs::two_pass::triangle
