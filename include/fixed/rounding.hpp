// fixed/rounding.hpp — right shift (division by 2^k) of built-in integers with a named rounding.
//
// C++20 defines >> of a negative signed value as an arithmetic shift (floor division by 2^k,
// [expr.shift]/3) and << of any value as multiplication modulo 2^N. Shifts by >= the width are
// never performed (they would be undefined): such quotients are computed separately, so every
// function here is well-defined and exact for every value of its type and every shift >= 0.
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

inline constexpr rounding all_roundings[] = {rounding::floor, rounding::toward_zero, rounding::nearest_ties_up,
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

// value / 2^shift rounded as R, exactly, for every value of T and every shift >= 0 (a shift < 0 is
// treated as 0). The result always fits T: for 1 <= shift < width, |quotient| <= |value| / 2 and the
// +1 of a round-up is applied to a quotient that is at most max/2; for shift >= width the quotient
// lies in [-1/2, 1) and rounds to -1, 0 or (unsigned, to nearest, shift == width) 1.
template <rounding R, std::integral T>
constexpr T shift_right(T value, int shift) noexcept {
  if (shift <= 0) return value;
  using U = std::make_unsigned_t<T>;
  if (shift >= width_v<T>) {
    // |value| <= 2^(width-1) <= 2^(shift-1). Only an unsigned value >= 2^(width-1) at shift == width
    // reaches 1/2; a negative one lies in [-1/2, 0): floor gives -1, every other mode 0 (the tie at
    // -1/2 goes up under both nearest modes, 0 being the even neighbour).
    if constexpr (std::is_unsigned_v<T>) {
      constexpr T half_range = static_cast<T>(T{1} << (width_v<T> - 1));
      const bool up = shift == width_v<T> && ((R == rounding::nearest_ties_up && value >= half_range) ||
                                              (R == rounding::nearest_ties_even && value > half_range));
      return static_cast<T>(up ? 1 : 0);
    } else {
      return static_cast<T>(R == rounding::floor && value < 0 ? -1 : 0);
    }
  }
  const U mask = static_cast<U>((U{1} << shift) - 1U);
  const U half = static_cast<U>(U{1} << (shift - 1));
  const U rem = static_cast<U>(static_cast<U>(value) & mask);  // value - floor(value/2^k)*2^k
  const T q = static_cast<T>(value >> shift);                  // floor: C++20 defines >> of a negative as arithmetic
  bool up = false;
  switch (R) {
    case rounding::floor: up = false; break;
    case rounding::toward_zero:
      if constexpr (std::is_signed_v<T>) up = value < 0 && rem != 0;
      break;
    case rounding::nearest_ties_up: up = rem >= half; break;
    case rounding::nearest_ties_even: up = rem > half || (rem == half && (static_cast<U>(q) & 1U) != 0); break;
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
