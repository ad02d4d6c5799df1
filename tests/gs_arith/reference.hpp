// tests/gs_arith/reference.hpp — independent closed-form expectations for the GS units.
//
// Written another way on purpose: plain `int` arithmetic, division instead of shifts, tables instead
// of switches, whole 32-bit words instead of fixed:: types. Each function restates one line of the
// facts digest ../shared/spec/gs-alu-facts.md; none calls the model.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace gs_ref {

// floor(p / d) for d > 0, from C++'s truncating division.
constexpr int floor_div(int p, int d) { return (p % d != 0 && p < 0) ? p / d - 1 : p / d; }
constexpr long long floor_div(long long p, long long d) { return (p % d != 0 && p < 0) ? p / d - 1 : p / d; }

constexpr int byte(std::uint32_t w, int i) { return static_cast<int>((w / (1u << (8 * i))) % 256u); }
constexpr std::uint32_t word(int r, int g, int b, int a) {
  return static_cast<std::uint32_t>(r) + 256u * static_cast<std::uint32_t>(g) + 65536u * static_cast<std::uint32_t>(b) +
         16777216u * static_cast<std::uint32_t>(a);
}
constexpr int clamp255(int v) { return std::min(std::max(v, 0), 255); }

// --- texture function (digest table). cf87: the fragment channel in 8.7 (value·128). ---
// keep_fraction: floor(Ct·Cf87 / 2^14); truncate_to_8: floor(Ct·floor(Cf87/128) / 128).
// Both products are non-negative, so floor and truncation agree (the digest's tfx_rounding note).
constexpr int modulate(int ct, int cf87, bool keep_fraction) {
  return keep_fraction ? (ct * cf87) / 16384 : (ct * (cf87 / 128)) / 128;
}
// tfx: 0 MODULATE, 1 DECAL, 2 HIGHLIGHT, 3 HIGHLIGHT2. Returns the 32-bit RGBA result.
constexpr std::uint32_t texture_function(int tfx, bool tcc_rgba, std::uint32_t texel, std::array<int, 4> cf87,
                                         bool keep_fraction) {
  const int af = cf87[3] / 128;
  int out[4];
  for (int ch = 0; ch < 3; ++ch) {
    const int ct = byte(texel, ch);
    const int m = modulate(ct, cf87[static_cast<std::size_t>(ch)], keep_fraction);
    const int by_mode[4] = {clamp255(m), ct, clamp255(m + af), clamp255(m + af)};
    out[ch] = by_mode[tfx];
  }
  const int at = byte(texel, 3);
  const int alpha_rgba[4] = {clamp255(modulate(at, cf87[3], keep_fraction)), at, clamp255(at + af), at};
  out[3] = tcc_rgba ? alpha_rgba[tfx] : af;
  return word(out[0], out[1], out[2], out[3]);
}

// --- alpha blend: ((A − B)·C >> 7) + D, floor (hardware) or truncation (what-if). ---
constexpr int blend_channel(int a, int b, int c, int d, bool floor_shift) {
  const int p = (a - b) * c;
  return (floor_shift ? floor_div(p, 128) : p / 128) + d;
}
// Selectors as the ALPHA_1 digits: A, B, D in {0 Cs, 1 Cd, 2 zero}; C in {0 As, 1 Ad, 2 FIX}.
// Returns the three wide RGB channels.
constexpr std::array<int, 3> alpha_blend(int A, int B, int C, int D, int fix, std::uint32_t cs, std::uint32_t cd,
                                         bool floor_shift) {
  const int alphas[3] = {byte(cs, 3), byte(cd, 3), fix};
  std::array<int, 3> out{};
  for (int ch = 0; ch < 3; ++ch) {
    const int colours[3] = {byte(cs, ch), byte(cd, ch), 0};
    out[static_cast<std::size_t>(ch)] = blend_channel(colours[A], colours[B], alphas[C], colours[D], floor_shift);
  }
  return out;
}

// --- COLCLAMP: clamp to 0..255, or keep v mod 256. ---
constexpr int colclamp(int v, bool clamp) { return clamp ? clamp255(v) : ((v % 256) + 256) % 256; }

// --- alpha test: ATST 0..7 = NEVER, ALWAYS, LESS, LEQUAL, EQUAL, GEQUAL, GREATER, NOTEQUAL. ---
constexpr bool atst_passes(int method, int a, int aref) {
  const int sign = (a > aref) - (a < aref);  // −1, 0, +1
  // For each method: passes when sign is −1, 0, +1.
  constexpr bool table[8][3] = {{false, false, false}, {true, true, true},  {true, false, false}, {true, true, false},
                                {false, true, false},  {false, true, true}, {false, false, true}, {true, false, true}};
  return table[method][sign + 1];
}
// {rgb, a, z} written. AFAIL 0 KEEP, 1 FB_ONLY, 2 ZB_ONLY, 3 RGB_ONLY (32-bit only, else FB_ONLY).
constexpr std::array<bool, 3> alpha_test(bool ate, int method, int aref, int afail, int a, bool target32) {
  if (!ate || atst_passes(method, a, aref)) return {true, true, true};
  const std::array<bool, 3> table[4] = {
      {false, false, false}, {true, true, false}, {false, false, true}, {true, !target32, false}};
  return table[afail];
}

// --- dither: 3-bit DIMX entry as an offset. ---
constexpr int dither_twos(int dm) { return dm < 4 ? dm : dm - 8; }
constexpr int dither_sign_magnitude(int dm) { return dm < 4 ? dm : 4 - dm; }
// DobieStation 68dd073e (issue 17): 4 -> −1, 5 -> −2, 6 -> −3, 7 -> −4.
constexpr int dither_inverted_magnitude(int dm) { return dm < 4 ? dm : 3 - dm; }

// --- bilinear as one 2-D weighted sum with weights a/16, b/16, the way DobieStation computes it: in
// doubles (exact here), truncated. ---
inline int weighted_sum_4(int t00, int t10, int t01, int t11, int a, int b) {
  const double x = a / 16.0, y = b / 16.0;
  return static_cast<int>((1 - x) * (1 - y) * t00 + x * (1 - y) * t10 + (1 - x) * y * t01 + x * y * t11);
}

// --- frame formats. ---
constexpr std::uint32_t pack16(std::uint32_t c) {
  return static_cast<std::uint32_t>(byte(c, 0) / 8 + 32 * (byte(c, 1) / 8) + 1024 * (byte(c, 2) / 8) +
                                    32768 * (byte(c, 3) / 128));
}
constexpr std::uint32_t read16(std::uint32_t w) {
  return word(static_cast<int>(w % 32) * 8, static_cast<int>(w / 32 % 32) * 8, static_cast<int>(w / 1024 % 32) * 8,
              static_cast<int>(w / 32768 % 2) * 128);
}
// Per bit: mask 1 keeps old.
constexpr std::uint32_t merge(std::uint32_t fresh, std::uint32_t old, std::uint32_t mask) {
  std::uint32_t out = 0;
  for (int i = 0; i < 32; ++i) {
    const std::uint32_t bit = 1u << i;
    out += (mask & bit) ? (old & bit) : (fresh & bit);
  }
  return out;
}

// --- bilinear: c0 + floor((c1 − c0)·w / 16). ---
constexpr int lerp16_4(int c0, int c1, int w) { return c0 + floor_div((c1 - c0) * w, 16); }

// --- CLUT CSM1: entries in 8×2 blocks of a 16×16 image. Index i -> (x, y). ---
constexpr int csm1_position(int i) {
  const int x = i % 8 + 8 * ((i / 16) % 2);
  const int y = 2 * (i / 32) + (i / 8) % 2;
  return 16 * y + x;
}

// --- Gouraud: (c1 − c0)·128 / n truncated toward zero. ---
constexpr long long gradient(int c0, int c1, long long n) {
  const long long num = static_cast<long long>(c1 - c0) * 128;
  const long long q = (num < 0 ? -num : num) / n;
  return num < 0 ? -q : q;
}

// --- Gouraud triangle plane, by barycentric coordinates instead of gradients. ---
// Vertices (x, y) in 1/16 pixel with one colour channel c. 128·plane(P) = 128·Σ c_i·A_i / det, where
// A_i is the signed area opposite vertex i as seen from P and det = A_0 + A_1 + A_2.
struct plane_vertex {
  long long x, y;
  int c;
};
constexpr long long cross(long long ax, long long ay, long long bx, long long by) { return ax * by - ay * bx; }
// Σ c_i·A_i (numerator over det) at point (px, py).
constexpr long long plane_numerator(const plane_vertex (&v)[3], long long px, long long py) {
  long long sum = 0;
  for (int i = 0; i < 3; ++i) {
    const plane_vertex& j = v[(i + 1) % 3];
    const plane_vertex& k = v[(i + 2) % 3];
    sum += v[i].c * cross(j.x - px, j.y - py, k.x - px, k.y - py);
  }
  return sum;
}
constexpr long long plane_det(const plane_vertex (&v)[3]) {
  return cross(v[1].x - v[0].x, v[1].y - v[0].y, v[2].x - v[0].x, v[2].y - v[0].y);
}
// The documented model: base = 128·c0 + trunc(128·(plane(ref) − c0)), steps trunc(128·Δplane) per
// pixel in x and y, value = clamp(base + i·dx + j·dy, 0, 0x7FFF) at ref + (i, j).
constexpr long long gouraud_plane_at(const plane_vertex (&v)[3], long long xr, long long yr, long long x, long long y) {
  const long long det = plane_det(v);
  const long long at_ref = plane_numerator(v, 16 * xr, 16 * yr);
  const long long base = 128 * v[0].c + (128 * (at_ref - v[0].c * det)) / det;
  const long long dx = (128 * (plane_numerator(v, 16 * xr + 16, 16 * yr) - at_ref)) / det;
  const long long dy = (128 * (plane_numerator(v, 16 * xr, 16 * yr + 16) - at_ref)) / det;
  const long long value = base + (x - xr) * dx + (y - yr) * dy;
  return std::min<long long>(std::max<long long>(value, 0), 0x7FFF);
}
// gouraud_setup = per_pixel: the exact plane at the pixel itself, 128·c0 + trunc(128·(plane(x, y) − c0)),
// clamped (the documented base value, with the pixel as its own reference).
constexpr long long gouraud_exact_at(const plane_vertex (&v)[3], long long x, long long y) {
  const long long det = plane_det(v);
  const long long value = 128 * v[0].c + (128 * (plane_numerator(v, 16 * x, 16 * y) - v[0].c * det)) / det;
  return std::min<long long>(std::max<long long>(value, 0), 0x7FFF);
}

// gouraud_setup = per_pixel_floor: floor(128·plane(x, y)), clamped (the value itself floored).
constexpr long long gouraud_floor_at(const plane_vertex (&v)[3], long long x, long long y) {
  long long num = 128 * plane_numerator(v, 16 * x, 16 * y), det = plane_det(v);
  if (det < 0) num = -num, det = -det;
  const long long value = num >= 0 ? num / det : -((-num + det - 1) / det);
  return std::min<long long>(std::max<long long>(value, 0), 0x7FFF);
}

}  // namespace gs_ref
