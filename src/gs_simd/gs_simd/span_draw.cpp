// gs_simd/span_draw.cpp — see span_draw.hpp: the per-target span loop (Highway foreach_target.h over
// pixel_units-inl.h) and the scalar test of its domain.
//
// U and V in lanes. An exact plane's value at a pixel is floor(n / den) (lifted by 1/64 under
// uv_convert floor_1_64), n = base + dx·x + dy·y. Write n = q·den + r with 0 <= r < den. Lane k of
// a vector whose first pixel has (q0, r0) holds n0 + k·dx = (q0 + A_k)·den + (r0 + B_k) with
// A_k = floor(k·dx / den), B_k = k·dx − A_k·den in [0, den): one carry (r0 + B_k >= den) makes it
// (q, r) again. The next vector, L pixels on, adds (A_L, B_L) and carries the same way. With den and
// |q| below 2^30, r0 + B_k < 2^31 and every value fits a 32-bit lane.
#include "gs_simd/span_draw.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gs_simd/span_draw.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "gs_arith/attribute_walk.hpp"
#include "gs_simd/pixel_units-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace gsdot3::simd::HWY_NAMESPACE {

// A plane's lanes over one triangle: n grows by s a pixel in x and by t a row; floor(n / den) is the
// value. The offsets (A_k, B_k) of lane k (stepped from (0, 0) by floor_div(s, den) and its remainder
// with one carry each), the step (A_L, B_L) of a vector, s and t as quotient and remainder (a run's
// start from the last run's), the lift's threshold (64·r >= 63·den, i.e. r >= ceil(63·den / 64); den
// when not lifted), and the value's bias and clamp.
struct plane_lanes {
  V a, b;
  std::int64_t den64, qs, rs, qt, rt;
  std::int32_t a_step, b_step, den, lift_at, bias, lo, hi;
  plane_lanes(std::int64_t s, std::int64_t t, std::int64_t d, bool lift, std::int32_t value_bias, std::int32_t low,
              std::int32_t high)
      : den64(d),
        qs(gs::floor_div(s, d)),
        rs(s - qs * d),
        qt(gs::floor_div(t, d)),
        rt(t - qt * d),
        bias(value_bias),
        lo(low),
        hi(high) {
    const D dv;
    const std::size_t lanes = hn::Lanes(dv);
    alignas(64) std::int32_t ak[HWY_MAX_BYTES / 4], bk[HWY_MAX_BYTES / 4];
    std::int64_t q = 0, r = 0;
    for (std::size_t k = 0; k < lanes; ++k) {
      ak[k] = static_cast<std::int32_t>(q), bk[k] = static_cast<std::int32_t>(r);
      q += qs, r += rs;
      if (r >= d) ++q, r -= d;
    }
    a_step = static_cast<std::int32_t>(q), b_step = static_cast<std::int32_t>(r);
    a = hn::Load(dv, ak), b = hn::Load(dv, bk);
    den = static_cast<std::int32_t>(d);
    lift_at = lift ? static_cast<std::int32_t>((63 * d + 63) / 64) : den;
  }
  // A UV plane (gs::plane::at).
  explicit plane_lanes(const gs::plane& p) : plane_lanes(p.dx, p.dy, p.den, p.lift_1_64, 0, p.lo, p.hi) {}
};

// (q, r) of the lanes of one run, stepped a vector at a time; (q0, r0) at the run's first pixel (x, y).
struct plane_walk_lanes {
  V q, r;
  std::int64_t q0 = 0, r0 = 0;
  int x = 0, y = 0;
  HWY_INLINE void carry(const plane_lanes& l) {
    const M c = hn::Not(hn::Lt(r, set(l.den)));
    q = hn::Add(q, hn::IfThenElseZero(c, set(1)));
    r = hn::Sub(r, hn::IfThenElseZero(c, set(l.den)));
  }
  HWY_INLINE void lanes(const plane_lanes& l) {
    q = hn::Add(set(static_cast<std::int32_t>(q0)), l.a);
    r = hn::Add(set(static_cast<std::int32_t>(r0)), l.b);
    carry(l);
  }
  // The first run: n is the numerator at its first pixel (x0, y0).
  HWY_INLINE void start(const plane_lanes& l, std::int64_t n, int x0, int y0) {
    q0 = gs::floor_div(n, l.den64), r0 = n - q0 * l.den64, x = x0, y = y0;
    lanes(l);
  }
  // A later run's first pixel (x0, y0): n moves by (x0 − x)·s + (y0 − y)·t, as quotients and remainders.
  HWY_INLINE void move(const plane_lanes& l, int x0, int y0) {
    const std::int64_t dx = x0 - x, dy = y0 - y;
    q0 += dx * l.qs + dy * l.qt, r0 += dx * l.rs + dy * l.rt, x = x0, y = y0;
    if (r0 < 0 || r0 >= l.den64) {  // the remainder back into [0, den)
      const std::int64_t c = gs::floor_div(r0, l.den64);
      q0 += c, r0 -= c * l.den64;
    }
    lanes(l);
  }
  void step(const plane_lanes& l) {
    q = hn::Add(q, set(l.a_step));
    r = hn::Add(r, set(l.b_step));
    carry(l);
  }
  // The lifted quotient plus the bias, clamped to [lo, hi].
  HWY_INLINE V value(const plane_lanes& l) const {
    const V up = hn::IfThenElseZero(hn::Not(hn::Lt(r, set(l.lift_at))), set(1));
    return hn::Min(hn::Max(hn::Add(hn::Add(q, up), set(l.bias)), set(l.lo)), set(l.hi));
  }
};

// The nearest texel's address (v << log2 width | u) of u16, v16 (12.4) in lanes: REPEAT masks, CLAMP
// clamps.
HWY_INLINE V texel_address(const nearest_texture& t, V u16, V v16) {
  V u = hn::ShiftRight<4>(u16), v = hn::ShiftRight<4>(v16);
  if (t.clamp) {
    u = hn::Min(hn::Max(u, set(0)), set(t.wmask));
    v = hn::Min(hn::Max(v, set(0)), set(t.hmask));
  } else {
    u = hn::And(u, set(t.wmask)), v = hn::And(v, set(t.hmask));
  }
  return hn::Or(hn::ShiftLeftSame(v, t.shift), u);
}
// The texel words of n addresses, in place: scalar loads, a PSMT8 index then its CLUT word, or the
// 32-bit texel. A run's texels are looked up together after its addresses and read back long after
// (draw_runs), so the loads overlap each other and the wide read back does not wait on them: lane by
// lane gathers of the index and then the CLUT word took a third of the triangle passes (perf, AMD
// EPYC with AVX-512, 2026-12-07).
HWY_INLINE void resolve_texels(const nearest_texture& t, std::int32_t* at, std::size_t n) {
  if (t.memory != nullptr) {  // through the texture's address table into the local memory
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t b = (t.address[static_cast<std::uint32_t>(at[k])] + t.base) & t.mask;
      at[k] = static_cast<std::int32_t>(t.words != nullptr ? t.words[memory_byte(t.memory, b)] : t.memory[b >> 2]);
    }
  } else if (t.index != nullptr) {
    for (std::size_t k = 0; k < n; ++k)
      at[k] = static_cast<std::int32_t>(t.words[t.index[static_cast<std::uint32_t>(at[k])]]);
  } else {
    for (std::size_t k = 0; k < n; ++k) at[k] = static_cast<std::int32_t>(t.texels[static_cast<std::uint32_t>(at[k])]);
  }
}

// Colour channel i of a per_pixel_floor plane (gouraud_numerator), clamped to the 8.7 channel's
// [0, 32767] (gouraud_channel::from_saturated).
HWY_INLINE plane_lanes colour_lanes(const gs::triangle_attributes& a, std::size_t i) {
  const gs::gouraud_exact_plane& e = a.colour.exact;
  const std::int64_t sign = e.det < 0 ? -1 : 1;
  return plane_lanes(sign * e.nx[i] * 2048, sign * e.ny[i] * 2048, sign * e.det, false,
                     static_cast<std::int32_t>(e.c0[i].value()), 0, 32767);
}

// The n pixels of a run from its k-th (n at most a vector) replaced by f(their vector of words): in a
// row-major buffer moved directly (part_vector when n is short of a vector); in the local memory
// (Swizzled) at their words (row[y] + column[x]) & mask, a whole vector by gather and scatter (the
// pixels of one row have distinct words), a part through a copy.
template <bool Swizzled, class F>
HWY_INLINE void merge(const span_target& fb, const span_run& run, std::size_t k, std::size_t n, F&& f) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  if constexpr (!Swizzled) {
    auto* p = reinterpret_cast<std::int32_t*>(fb.words + static_cast<std::size_t>(run.y) * fb.stride +
                                              static_cast<std::size_t>(run.x0) + k);
    if (n == lanes) return hn::StoreU(f(hn::LoadU(d, p)), d, p);
    return part_vector(p, n, f);
  } else {
    auto* memory = reinterpret_cast<std::int32_t*>(fb.words);
    const std::uint32_t row = fb.row[run.y];
    const std::uint32_t* column = fb.column + static_cast<std::size_t>(run.x0) + k;
    if (n == lanes) {
      const V at = hn::And(
          hn::Add(set(static_cast<std::int32_t>(row)), hn::LoadU(d, reinterpret_cast<const std::int32_t*>(column))),
          set(static_cast<std::int32_t>(fb.mask)));
      return hn::ScatterIndex(f(hn::GatherIndex(d, memory, at)), d, memory, at);
    }
    alignas(64) std::int32_t copy[HWY_MAX_BYTES / 4] = {};
    std::uint32_t at[HWY_MAX_BYTES / 4];
    for (std::size_t j = 0; j < n; ++j) at[j] = (row + column[j]) & fb.mask, copy[j] = memory[at[j]];
    hn::Store(f(hn::Load(d, copy)), d, copy);
    for (std::size_t j = 0; j < n; ++j) memory[at[j]] = copy[j];
  }
}

// The runs, Gouraud: the four channels stepped in lanes too; else the colour is one value. In chunks of
// runs whose vectors fit `slots`: their U, V walked and their texel addresses stored, the texels looked
// up (resolve_texels), then each vector of pixels through the units with its texels read back.
template <bool Gouraud, bool Swizzled>
HWY_INLINE void draw_runs(const gs::gs_registers& regs, const gs::model_options& o, const gs::triangle_attributes& a,
                          const nearest_texture& tex, const span_run* runs, std::size_t count, const span_target& fb) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const bool textured = tex.textured();
  const plane_lanes pu(a.u), pv(a.v);
  const gs::fragment_colour c = a.colour_at(runs[0].x0, runs[0].y);  // a flat plane's one value
  rgba_v cf = flat(c);
  auto channel = [&](std::size_t i) { return Gouraud ? colour_lanes(a, i) : pu; };  // unused when flat
  const plane_lanes pr = channel(0), pg = channel(1), pb = channel(2), pa = channel(3);
  const V iota = hn::Iota(d, 0);
  plane_walk_lanes u, v, r, g, b, al;
  constexpr std::size_t slots = 2 * max_run;  // 16 KiB of texels; a run is at most max_run pixels (span_applies)
  alignas(64) std::int32_t texel[slots];
  auto vectors = [&](const span_run& run) { return (static_cast<std::size_t>(run.n) + lanes - 1) / lanes * lanes; };
  for (std::size_t first = 0, end = 0; first < count; first = end) {
    std::size_t used = 0;
    for (end = first; end < count && used + vectors(runs[end]) <= slots; ++end) {
      const span_run& run = runs[end];
      if (!textured) {
        used += vectors(run);
        continue;
      }
      if (end == 0) {
        u.start(pu, a.u.base + a.u.dx * run.x0 + a.u.dy * run.y, run.x0, run.y);
        v.start(pv, a.v.base + a.v.dx * run.x0 + a.v.dy * run.y, run.x0, run.y);
      } else {
        u.move(pu, run.x0, run.y), v.move(pv, run.x0, run.y);
      }
      for (std::size_t k = 0; k < static_cast<std::size_t>(run.n); k += lanes, used += lanes) {
        if (k != 0) u.step(pu), v.step(pv);
        hn::Store(texel_address(tex, u.value(pu), v.value(pv)), d, texel + used);
      }
    }
    if (textured) resolve_texels(tex, texel, used);
    used = 0;
    for (std::size_t i = first; i < end; ++i) {
      const span_run& run = runs[i];
      if constexpr (Gouraud) {
        if (i == 0) {
          r.start(pr, gouraud_numerator(a, 0, run.x0, run.y), run.x0, run.y);
          g.start(pg, gouraud_numerator(a, 1, run.x0, run.y), run.x0, run.y);
          b.start(pb, gouraud_numerator(a, 2, run.x0, run.y), run.x0, run.y);
          al.start(pa, gouraud_numerator(a, 3, run.x0, run.y), run.x0, run.y);
        } else {
          r.move(pr, run.x0, run.y), g.move(pg, run.x0, run.y), b.move(pb, run.x0, run.y), al.move(pa, run.x0, run.y);
        }
      }
      const V y = set(run.y);
      for (std::size_t k = 0, n = static_cast<std::size_t>(run.n); k < n; k += lanes, used += lanes) {
        if constexpr (Gouraud) {
          if (k != 0) r.step(pr), g.step(pg), b.step(pb), al.step(pa);
          cf = {r.value(pr), g.value(pg), b.value(pb), al.value(pa)};
        }
        const V t = textured ? hn::Load(d, texel + used) : set(0);
        const V x = hn::Add(set(run.x0 + static_cast<std::int32_t>(k)), iota);
        auto pixels = [&](V dst) __attribute__((always_inline)) { return pixel_pipeline(regs, o, t, cf, dst, x, y); };
        merge<Swizzled>(fb, run, k, std::min(lanes, n - k), pixels);
      }
    }
  }
}

// depth_rows (span_draw.hpp): a fixed-point plane's value n >> 16 is floor(n / 65536), the exact form's
// lanes with den 65536 and no lift. The lanes are set up once for all rows; each row moves the walk from
// the last. Lanes divide 64, so a vector's pass bits never straddle two words.
std::size_t depth_rows_lanes(const gs::test_reg& test, const gs::zbuf_reg& zbuf, const gs::plane& p, std::uint32_t keep,
                             const span_run* rows, std::size_t count, std::uint32_t* z, std::size_t stride,
                             std::uint64_t* pass) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const plane_lanes l = p.den == 0 ? plane_lanes(p.dx, p.dy, 65536, false, 0, p.lo, p.hi) : plane_lanes(p);
  const V kept = set(static_cast<std::int32_t>(keep));
  plane_walk_lanes walk;
  std::size_t passed = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const span_run& row = rows[i];
    const auto n = static_cast<std::size_t>(row.n);
    if (i == 0)
      walk.start(l, p.base + p.dx * row.x0 + p.dy * row.y, row.x0, row.y);
    else
      walk.move(l, row.x0, row.y);
    for (std::size_t w = 0; w < (n + 63) / 64; ++w) pass[w] = 0;
    auto* words = reinterpret_cast<std::int32_t*>(z + static_cast<std::size_t>(row.y) * stride +
                                                  static_cast<std::size_t>(row.x0));
    for (std::size_t k = 0; k < n; k += lanes) {
      if (k != 0) walk.step(l);
      M tested = hn::FirstN(d, 0);
      auto test_and_write = [&](V old) __attribute__((always_inline)) {
        const depth_lanes t = depth_test(test, zbuf, walk.value(l), old);
        tested = t.pass;
        return hn::IfThenElse(t.write, masked_merge(t.zs, old, kept), old);
      };
      const std::size_t m = std::min(lanes, n - k);
      if (m == lanes)
        hn::StoreU(test_and_write(hn::LoadU(d, words + k)), d, words + k);
      else
        part_vector(words + k, m, test_and_write);
      const M in = hn::And(tested, hn::FirstN(d, m));
      std::uint8_t bytes[8] = {};
      hn::StoreMaskBits(d, in, bytes);
      std::uint64_t bits = 0;
      for (std::size_t b = 0; b < (lanes + 7) / 8; ++b) bits |= std::uint64_t{bytes[b]} << (8 * b);
      pass[k / 64] |= bits << (k % 64);
      passed += hn::CountTrue(d, in);
    }
    pass += (n + 63) / 64;
  }
  return passed;
}

void span_triangle_lanes(const gs::gs_registers& regs, const gs::model_options& o, const gs::triangle_attributes& a,
                         const nearest_texture& tex, const span_run* runs, std::size_t count, const span_target& fb) {
  if (count == 0) return;
  const bool gouraud = !gs::flat_colour(a);
  if (fb.row != nullptr) {
    if (gouraud) return draw_runs<true, true>(regs, o, a, tex, runs, count, fb);
    return draw_runs<false, true>(regs, o, a, tex, runs, count, fb);
  }
  if (gouraud) return draw_runs<true, false>(regs, o, a, tex, runs, count, fb);
  draw_runs<false, false>(regs, o, a, tex, runs, count, fb);
}

}  // namespace gsdot3::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace gsdot3::simd {

HWY_EXPORT(span_triangle_lanes);
HWY_EXPORT(depth_rows_lanes);

namespace {

constexpr std::int64_t lane_limit = std::int64_t{1} << 30;

// Whether a plane (numerator n(x, y), stepping by s a pixel, over den) fits 32-bit lanes on the
// rectangle: den below 2^30, the quotients at its corners (a plane's extremes over it) within
// [−2^30, 2^30), and a pixel's step within ±2^24 (16 lanes' step and a vector's carry); each bound
// on n / den checked as one on n (den > 0), no division.
template <class Numerator>
bool fits_lanes(std::int64_t s, std::int64_t den, Numerator&& n, int x0, int y0, int x1, int y1) noexcept {
  if (den <= 0 || den >= lane_limit) return false;
  if (s <= -(lane_limit >> 6) * den || s >= (lane_limit >> 6) * den) return false;
  for (const int x : {x0, x1 - 1})
    for (const int y : {y0, y1 - 1})
      if (const std::int64_t v = n(x, y); v < -lane_limit * den || v >= lane_limit * den) return false;
  return true;
}

}  // namespace

bool span_applies(const gs::triangle_attributes& a, int x0, int y0, int x1, int y1) noexcept {
  if (x0 >= x1 || y0 >= y1) return true;  // nothing to draw
  if (x1 - x0 > max_run) return false;    // a run fits draw_runs' chunk
  if (!fits_lanes(
          a.u.dx, a.u.den, [&](int x, int y) { return a.u.base + a.u.dx * x + a.u.dy * y; }, x0, y0, x1, y1) ||
      !fits_lanes(
          a.v.dx, a.v.den, [&](int x, int y) { return a.v.base + a.v.dx * x + a.v.dy * y; }, x0, y0, x1, y1))
    return false;
  if (gs::flat_colour(a)) return true;
  // Gouraud: the exact plane floored, whose pixel distances clamp_distance leaves alone on the rectangle.
  if (a.setup != gs::gouraud_setup::per_pixel_floor) return false;
  for (const std::int64_t k : {std::int64_t{x0} + a.offset_x, std::int64_t{x1} - 1 + a.offset_x,
                               std::int64_t{y0} + a.offset_y, std::int64_t{y1} - 1 + a.offset_y})
    if (k <= -65536 || k > 65536) return false;
  const gs::gouraud_exact_plane& e = a.colour.exact;
  const std::int64_t sign = e.det < 0 ? -1 : 1;
  for (std::size_t i = 0; i < 4; ++i) {
    auto n = [&](int x, int y) { return gouraud_numerator(a, i, x, y); };
    if (!fits_lanes(sign * e.nx[i] * 2048, sign * e.det, n, x0, y0, x1, y1)) return false;
  }
  return true;
}

bool depth_row_applies(const gs::plane& p, int x0, int y0, int x1, int y1) noexcept {
  if (x0 >= x1 || y0 >= y1) return true;
  return fits_lanes(
      p.dx, p.den == 0 ? 65536 : p.den, [&](int x, int y) { return p.base + p.dx * x + p.dy * y; }, x0, y0, x1, y1);
}

std::size_t depth_rows(const gs::test_reg& test, const gs::zbuf_reg& zbuf, const gs::plane& p, std::uint32_t keep,
                       const span_run* rows, std::size_t count, std::uint32_t* z, std::size_t stride,
                       std::uint64_t* pass) {
  return HWY_DYNAMIC_DISPATCH(depth_rows_lanes)(test, zbuf, p, keep, rows, count, z, stride, pass);
}

void span_triangle(const gs::gs_registers& regs, const gs::model_options& o, const gs::triangle_attributes& a,
                   const nearest_texture& tex, const span_run* runs, std::size_t count, const span_target& fb) {
  HWY_DYNAMIC_DISPATCH(span_triangle_lanes)(regs, o, a, tex, runs, count, fb);
}

}  // namespace gsdot3::simd
#endif  // HWY_ONCE
