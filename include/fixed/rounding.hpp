// fixed/rounding.hpp — right shift (division by 2^k) of built-in integers with a named rounding.
//
// C++20 defines >> of a negative signed value as an arithmetic shift (floor division by 2^k,
// [expr.shift]/3) and << of any value as multiplication modulo 2^N, so every function here is
// well-defined for every value of its type and every shift 0 <= k < width.
#pragma once

#include <concepts>
#include <limits>
#include <type_traits>

namespace fixed {

// How a quotient by 2^k is rounded to an integer.
enum class rounding {
  floor,              // toward -infinity (arithmetic shift); the GS blend's >> 7
  toward_zero,        // truncation, as C's integer division
  nearest_ties_up,    // to nearest, exact halves toward +infinity
  nearest_ties_even,  // to nearest, exact halves to the even neighbour (banker's rounding)
};

inline constexpr rounding all_roundings[] = {rounding::floor, rounding::toward_zero,
                                             rounding::nearest_ties_up,
                                             rounding::nearest_ties_even};

constexpr const char* name(rounding r) noexcept {
  switch (r) {
    case rounding::floor: return "floor";
    case rounding::toward_zero: return "toward_zero";
    case rounding::nearest_ties_up: return "nearest_ties_up";
    case rounding::nearest_ties_even: return "nearest_ties_even";
  }
  return "?";
}

template <std::integral T>
inline constexpr int width_v = std::numeric_limits<std::make_unsigned_t<T>>::digits;

// value / 2^shift rounded as R. Precondition: 0 <= shift < width_v<T> (checked in constant
// evaluation; a runtime violation is clamped to width-1 rather than invoking undefined behaviour).
// The result always fits T: |quotient| <= |value| / 2 for shift >= 1, and the +1 of a round-up is
// applied to a quotient that is at most max/2.
template <rounding R, std::integral T>
constexpr T shift_right(T value, int shift) noexcept {
  if (shift <= 0) return value;
  if (shift >= width_v<T>) shift = width_v<T> - 1;
  using U = std::make_unsigned_t<T>;
  const U mask = static_cast<U>((U{1} << shift) - 1U);
  const U half = static_cast<U>(U{1} << (shift - 1));
  const U rem = static_cast<U>(static_cast<U>(value) & mask);  // value - floor(value/2^k)*2^k
  const T q = static_cast<T>(value >> shift);                   // floor (arithmetic for signed)
  bool up = false;
  switch (R) {
    case rounding::floor: up = false; break;
    case rounding::toward_zero:
      if constexpr (std::is_signed_v<T>) up = value < 0 && rem != 0;
      break;
    case rounding::nearest_ties_up: up = rem >= half; break;
    case rounding::nearest_ties_even:
      up = rem > half || (rem == half && (static_cast<U>(q) & 1U) != 0);
      break;
  }
  return static_cast<T>(q + (up ? 1 : 0));
}

// Runtime-selected rounding, for callers whose rounding is a model option.
template <std::integral T>
constexpr T shift_right(T value, int shift, rounding r) noexcept {
  switch (r) {
    case rounding::floor: return shift_right<rounding::floor>(value, shift);
    case rounding::toward_zero: return shift_right<rounding::toward_zero>(value, shift);
    case rounding::nearest_ties_up: return shift_right<rounding::nearest_ties_up>(value, shift);
    case rounding::nearest_ties_even: return shift_right<rounding::nearest_ties_even>(value, shift);
  }
  return value;
}

}  // namespace fixed
