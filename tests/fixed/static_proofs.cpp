// tests/fixed/static_proofs.cpp — the rounding and overflow identities of include/fixed, proven by
// static_assert. If this file compiles they hold; it is part of fixed_unit, so the default build
// proves them. Domains (each enumerated in full):
//  - rounding, all 4 modes: every 16-bit input (2^16 int16_t and 2^16 uint16_t) at k = 7, the GS's
//    blend and modulate shift (2^19 cases); and every k in 0..15 for the 512 int16_t inputs
//    -256..255 and the 512 uint16_t inputs 0..511 (2^16 cases, so k >= the value's width is covered).
//    The full 2^16 x 16-shift domain is the runtime test fixed_exhaustive: g++ 12 evaluates about
//    65 000 loop iterations per second in constant evaluation, so 2^23 cases would take minutes;
//  - overflow (wrap, saturate, both via narrow<O>): every 16-bit input narrowed to u8, u9 and
//    (int16_t only: a signed result needs a signed type) s8, s9 (6 x 2^16 cases). checked is left to
//    fixed_exhaustive (every 17-bit input): evaluating its std::optional 393 216 times doubled this
//    file's compile time (to 28 s of g++ CPU) and took 1.5 GB.
// Each identity characterises the result without computing it the library's way:
//  - rounding: q = round(v / 2^k) satisfies the mode's defining inequality on e = v - q·2^k;
//  - wrap lies in range and differs from v by a multiple of 2^n; saturate is v when v is in range
//    and otherwise the nearer bound.
// The inputs are split into pages so that each static_assert stays inside the compilers' default
// constexpr budgets (g++ -fconstexpr-ops-limit 2^25, clang -fconstexpr-steps 2^20).
#include <cstdint>
#include <limits>
#include <utility>

#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"

namespace {

using fixed::rounding;
using fixed::signedness;

// The defining inequality of q = round_r(v / 2^k), on e = v - q·2^k.
constexpr bool rounding_identity(rounding r, std::int64_t v, int k, std::int64_t q) {
  const std::int64_t d = std::int64_t{1} << k;  // 2^k (a shift of 1, not of the value)
  const std::int64_t e = v - q * d;
  switch (r) {
    case rounding::floor: return 0 <= e && e < d;  // q <= v/d < q + 1
    case rounding::toward_zero: return v >= 0 ? 0 <= e && e < d : -d < e && e <= 0;
    case rounding::nearest_ties_up: return -d <= 2 * e && 2 * e < d;  // q - 1/2 < v/d <= q + 1/2
    case rounding::nearest_ties_even:
      return -d <= 2 * e && 2 * e <= d && (2 * e == d || 2 * e == -d ? q % 2 == 0 : true);
  }
  return false;
}

// The value of T with index i, counting from T's lowest value.
template <class T>
constexpr T nth_value(std::int64_t i) {
  return static_cast<T>(std::int64_t{std::numeric_limits<T>::min()} + i);
}

template <class T, rounding R, int KFirst, int KLast, std::int64_t First, std::int64_t Count>
constexpr bool rounding_page_holds() {
  for (std::int64_t i = First; i < First + Count; ++i) {
    const T v = nth_value<T>(i);
    for (int k = KFirst; k <= KLast; ++k) {
      if (!rounding_identity(R, v, k, fixed::shift_right<R>(v, k))) return false;
    }
  }
  return true;
}

template <int N, signedness S, class T, std::int64_t First, std::int64_t Count>
constexpr bool overflow_page_holds() {
  using range = fixed::bit_range<N, S>;
  constexpr std::int64_t modulus = std::int64_t{1} << N;
  for (std::int64_t i = First; i < First + Count; ++i) {
    const T v = nth_value<T>(i);
    const std::int64_t x = v;
    const bool in_range = range::min <= x && x <= range::max;
    const std::int64_t w = fixed::wrap<N, S>(v);
    const std::int64_t s = fixed::saturate<N, S>(v);
    const bool holds = range::min <= w && w <= range::max && (x - w) % modulus == 0 &&
                       s == (in_range         ? x
                             : x < range::min ? range::min
                                              : range::max) &&
                       fixed::narrow<N, S, fixed::overflow::wrap>(v) == w &&
                       fixed::narrow<N, S, fixed::overflow::saturate>(v) == s;
    if (!holds) return false;
  }
  return true;
}

constexpr std::int64_t page_size = 4096;
constexpr std::int64_t pages = 65536 / page_size;

// One static_assert per page, so each is its own constant evaluation with its own budget; a failing
// page is named in the diagnostic by its template arguments.
template <class T, rounding R, std::int64_t Page>
struct gs_shift_page {
  static_assert(rounding_page_holds<T, R, 7, 7, Page * page_size, page_size>());
  static constexpr bool proven = true;
};
template <int N, signedness S, class T, std::int64_t Page>
struct overflow_page {
  static_assert(overflow_page_holds<N, S, T, Page * page_size, page_size>());
  static constexpr bool proven = true;
};

template <class T, rounding R, std::int64_t... Page>
constexpr bool gs_shift_proven(std::integer_sequence<std::int64_t, Page...>) {
  return (gs_shift_page<T, R, Page>::proven && ...);
}
template <int N, signedness S, class T, std::int64_t... Page>
constexpr bool overflow_proven(std::integer_sequence<std::int64_t, Page...>) {
  return (overflow_page<N, S, T, Page>::proven && ...);
}

// Every mode at every shift 0..15 on 512 values from `first` (one page: 512 x 16 shifts).
template <class T, std::int64_t First>
constexpr bool every_shift_proven() {
  return rounding_page_holds<T, rounding::floor, 0, 15, First, 512>() &&
         rounding_page_holds<T, rounding::toward_zero, 0, 15, First, 512>() &&
         rounding_page_holds<T, rounding::nearest_ties_up, 0, 15, First, 512>() &&
         rounding_page_holds<T, rounding::nearest_ties_even, 0, 15, First, 512>();
}

template <class T>
constexpr bool gs_shift_proven_all_modes() {
  constexpr auto all = std::make_integer_sequence<std::int64_t, pages>{};
  return gs_shift_proven<T, rounding::floor>(all) && gs_shift_proven<T, rounding::toward_zero>(all) &&
         gs_shift_proven<T, rounding::nearest_ties_up>(all) && gs_shift_proven<T, rounding::nearest_ties_even>(all);
}

template <class T, int N, signedness S>
constexpr bool overflow_proven_all() {
  return overflow_proven<N, S, T>(std::make_integer_sequence<std::int64_t, pages>{});
}

static_assert(gs_shift_proven_all_modes<std::int16_t>(), "rounding identities, all 2^16 int16_t, k = 7");
static_assert(gs_shift_proven_all_modes<std::uint16_t>(), "rounding identities, all 2^16 uint16_t, k = 7");
static_assert(every_shift_proven<std::int16_t, 32768 - 256>(), "rounding identities, int16_t -256..255, k = 0..15");
static_assert(every_shift_proven<std::uint16_t, 0>(), "rounding identities, uint16_t 0..511, k = 0..15");

static_assert(overflow_proven_all<std::int16_t, 8, signedness::is_signed>(), "overflow identities, all int16_t to s8");
static_assert(overflow_proven_all<std::int16_t, 9, signedness::is_signed>(), "overflow identities, all int16_t to s9");
static_assert(overflow_proven_all<std::int16_t, 8, signedness::is_unsigned>(),
              "overflow identities, all int16_t to u8");
static_assert(overflow_proven_all<std::int16_t, 9, signedness::is_unsigned>(),
              "overflow identities, all int16_t to u9");
static_assert(overflow_proven_all<std::uint16_t, 8, signedness::is_unsigned>(),
              "overflow identities, all uint16_t to u8");
static_assert(overflow_proven_all<std::uint16_t, 9, signedness::is_unsigned>(),
              "overflow identities, all uint16_t to u9");

}  // namespace
