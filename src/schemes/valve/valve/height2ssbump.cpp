// valve/height2ssbump.cpp — see height2ssbump.hpp for the algorithm and its source.
#include "valve/height2ssbump.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>

namespace gsdot3::valve {

namespace {

int wrap(int v, int n) noexcept { return ((v % n) + n) % n; }

vec3<float> sub(const vec3<float>& a, const vec3<float>& b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
vec3<float> cross(const vec3<float>& a, const vec3<float>& b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
vec3<float> unit(const vec3<float>& v) noexcept {
  const float len = std::sqrt(dot(v, v));
  return len > 0.0f ? vec3<float>{v.x / len, v.y / len, v.z / len} : v;
}

// HaltonSequenceGenerator_t::GetElement in float, for the member seed k.
float halton(int k, int base) noexcept {
  const float fbase = static_cast<float>(base);
  float ret = 0.0f, base_inv = 1.0f / fbase;
  for (; k != 0; k /= base) {
    ret += static_cast<float>(k % base) * base_inv;
    base_inv /= fbase;
  }
  return ret;
}

// Runs f(y) for every row y on `threads` workers; progress after each row that no other worker is
// reporting, and 1.0 once when every row is done (after the workers have joined: the last row's
// worker may find another one reporting, so completion is never left to the rows).
template <class F>
void for_rows(int h, unsigned threads, const std::function<void(double)>& progress, F&& f) {
  std::atomic<int> next{0}, done{0};
  std::atomic_flag reporting = ATOMIC_FLAG_INIT;
  auto work = [&] {
    for (int y = next++; y < h; y = next++) {
      f(y);
      const int d = ++done;
      if (progress && d < h && !reporting.test_and_set()) {
        progress(static_cast<double>(d) / h);
        reporting.clear();
      }
    }
  };
  const unsigned n =
      std::max(1U, std::min(threads == 0 ? std::thread::hardware_concurrency() : threads, static_cast<unsigned>(h)));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  if (progress) progress(1.0);
}

// Möller–Trumbore, both faces: does the segment o + t·d, t ∈ (0, 1], cross triangle (a, b, c)?
bool hits(const vec3<float>& o, const vec3<float>& d, const vec3<float>& a, const vec3<float>& b,
          const vec3<float>& c) noexcept {
  const vec3<float> e1 = sub(b, a), e2 = sub(c, a), p = cross(d, e2);
  const float det = dot(e1, p);
  if (std::fabs(det) < 1e-12f) return false;
  const float inv = 1.0f / det;
  const vec3<float> s = sub(o, a);
  const float u = dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return false;
  const vec3<float> q = cross(s, e1);
  const float v = dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return false;
  const float t = dot(e2, q) * inv;
  return t > 0.0f && t <= 1.0f;
}

struct height_field {
  const std::vector<float>& h;
  int w, hh;
  float scale;
  int x_lo, x_hi, y_lo, y_hi;  // cells present in Source's tiled triangle soup
  float z_max;
  vec3<float> corner(int x, int y) const noexcept {
    return {static_cast<float>(x), static_cast<float>(y),
            scale * h[static_cast<std::size_t>(wrap(y, hh) * w + wrap(x, w))]};
  }
  bool cell_blocks(int cx, int cy, const vec3<float>& o, const vec3<float>& d) const noexcept {
    if (cx < x_lo || cx > x_hi || cy < y_lo || cy > y_hi) return false;
    const auto v0 = corner(cx, cy), v1 = corner(cx + 1, cy), v2 = corner(cx + 1, cy + 1), v3 = corner(cx, cy + 1);
    return hits(o, d, v0, v1, v2) || hits(o, d, v0, v3, v2);
  }
  // Walks the cells under the segment (2-D DDA), stopping once the ray is above every triangle.
  bool blocked(const vec3<float>& o, const vec3<float>& d) const noexcept {
    int cx = static_cast<int>(std::floor(o.x)), cy = static_cast<int>(std::floor(o.y));
    const int sx = d.x > 0 ? 1 : -1, sy = d.y > 0 ? 1 : -1;
    const float inf = std::numeric_limits<float>::infinity();
    const float dx = d.x != 0 ? std::fabs(1.0f / d.x) : inf, dy = d.y != 0 ? std::fabs(1.0f / d.y) : inf;
    float tx = d.x > 0 ? (static_cast<float>(cx + 1) - o.x) * dx : d.x < 0 ? (o.x - static_cast<float>(cx)) * dx : inf;
    float ty = d.y > 0 ? (static_cast<float>(cy + 1) - o.y) * dy : d.y < 0 ? (o.y - static_cast<float>(cy)) * dy : inf;
    float t = 0.0f;
    while (t <= 1.0f) {
      // The origin is a vertex: the 2×2 cells meeting there are all under the ray's start.
      if (t == 0.0f &&
          (cell_blocks(cx - 1, cy - 1, o, d) || cell_blocks(cx, cy - 1, o, d) || cell_blocks(cx - 1, cy, o, d)))
        return true;
      if (cell_blocks(cx, cy, o, d)) return true;
      if (o.z + d.z * t > z_max) return false;
      if (tx < ty) {
        t = tx, tx += dx, cx += sx;
      } else {
        t = ty, ty += dy, cy += sy;
      }
      if (cx < x_lo - 1 || cx > x_hi + 1 || cy < y_lo - 1 || cy > y_hi + 1) return false;
    }
    return false;
  }
};

}  // namespace

std::vector<float> bilateral_filter(const std::vector<float>& height, int w, int h, int radius, float threshold) {
  if (radius <= 0) return height;
  std::vector<float> out(height.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float centre = height[static_cast<std::size_t>(y * w + x)];
      float sum_weights = 0.0f, filter_sum = 0.0f;
      for (int iy = -radius; iy <= radius; ++iy)
        for (int ix = -radius; ix <= radius; ++ix) {
          const float p = height[static_cast<std::size_t>(wrap(y + iy, h) * w + wrap(x + ix, w))];
          const float g =
              std::exp(-static_cast<float>(ix * ix + iy * iy) * (1.0f / (2.0f * static_cast<float>(radius) * 0.033f)));
          const float diff = std::fabs(centre - p);
          const float s = diff > threshold ? 0.0f : 1.0f - diff / threshold;  // FLerp(1, 0, 0, threshold, diff)
          sum_weights += s * g;
          filter_sum += s * g * p;
        }
      out[static_cast<std::size_t>(y * w + x)] = filter_sum / sum_weights;  // the centre has weight 1
    }
  return out;
}

std::vector<vec3<float>> vertex_normals(const std::vector<float>& height, int w, int h, float bump_scale) {
  auto vert = [&](int x, int y) {
    return vec3<float>{static_cast<float>(x), static_cast<float>(y),
                       bump_scale * height[static_cast<std::size_t>(y * w + x)]};
  };
  std::vector<vec3<float>> normals(height.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      vec3<float> avg{};
      for (int xo = -1; xo <= 1; ++xo)
        for (int yo = -1; yo <= 1; ++yo) {
          const int x0 = wrap(x + xo, w), y0 = wrap(y + yo, h), x1 = (x0 + 1) % w, y1 = (y0 + 1) % h;
          const vec3<float> p0 = vert(x0, y0);
          vec3<float> n1 = cross(sub(vert(x1, y0), p0), sub(vert(x0, y1), p0));
          if (n1.z < 0) n1 = {-n1.x, -n1.y, -n1.z};
          vec3<float> n2 = cross(sub(vert(x, y1), p0), sub(vert(x1, y1), p0));  // Source: centre column x
          if (n2.z < 0) n2 = {-n2.x, -n2.y, -n2.z};
          n1 = unit(n1), n2 = unit(n2);
          avg = {avg.x + n1.x + n2.x, avg.y + n1.y + n2.y, avg.z + n1.z + n2.z};
        }
      normals[static_cast<std::size_t>(y * w + x)] = unit(avg);
    }
  return normals;
}

std::vector<vec3<float>> trace_directions(int rays) {
  std::vector<vec3<float>> dirs;
  for (int r = 0; r < rays; ++r) {
    const int k = r + 2;  // the member seed after NextValue's seed++
    const float z = 2.0f * halton(k, 2) - 1.0f;
    const float phi = std::acos(z);
    const float theta = 2.0f * std::numbers::pi_v<float> * halton(k, 3);
    const float sin_p = std::sin(phi);
    dirs.push_back({std::cos(theta) * sin_p, std::sin(theta) * sin_p, std::fabs(z)});
  }
  return dirs;
}

std::vector<vec3<float>> height2ssbump(const std::vector<float>& height_in, int w, int h,
                                       const height2ssbump_options& o) {
  const std::vector<float> height = bilateral_filter(height_in, w, h, o.filter_radius, o.filter_threshold);
  const std::vector<vec3<float>> normals = vertex_normals(height, w, h, o.bump_scale);
  const std::vector<vec3<float>> dirs = trace_directions(o.rays);
  const float length = static_cast<float>((1 + 2 * o.tile_reps) * std::max(w, h));
  // NREPS_TILE = 1: Source adds the 3×3 tiles, the outer ones only from (or up to) the half width,
  // so the cells span [W/2 − W, W + W/2] × [H/2 − H, H + H/2]; 0: the map alone.
  const bool tiled = o.tile_reps > 0;
  const height_field field{height,
                           w,
                           h,
                           o.bump_scale,
                           tiled ? w / 2 - w : 0,
                           tiled ? w + w / 2 : w - 1,
                           tiled ? h / 2 - h : 0,
                           tiled ? h + h / 2 : h - 1,
                           o.bump_scale * *std::max_element(height.begin(), height.end())};
  std::vector<vec3<float>> out(height.size());
  const auto& B = bumpvects_basis_float;
  for_rows(h, o.threads, o.progress, [&](int y) {
    std::vector<char> open(dirs.size());
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x);
      const vec3<float> origin{static_cast<float>(x), static_cast<float>(y), o.bump_scale * height[i] + o.origin_bias};
      for (std::size_t r = 0; r < dirs.size(); ++r) {
        const vec3<float> d{dirs[r].x * length, dirs[r].y * length, dirs[r].z * length};
        open[r] = !field.blocked(origin, d);
      }
      float value[3];
      for (int c = 0; c < 3; ++c) {
        const auto& b = B[static_cast<std::size_t>(c)];
        const float ndotl = dot(b, normals[i]);
        if (ndotl < 0) {
          value[c] = 0.0f;
          continue;
        }
        float sum = 0.0f, possible = 0.0f;
        for (std::size_t r = 0; r < dirs.size(); ++r) {
          const float dd = dot(b, dirs[r]);
          if (dd > 0) {
            possible += dd;
            if (open[r]) sum += dd;
          }
        }
        value[c] = dirs.empty() ? ndotl : ndotl * sum / possible;
      }
      out[i] = {value[0], value[1], value[2]};
    }
  });
  return out;
}

}  // namespace gsdot3::valve
