// fixed/overflow.hpp — narrowing a built-in integer to N bits with a named overflow behaviour.
//
// Ranges: an N-bit signed value lies in [-2^(N-1), 2^(N-1) - 1], an N-bit unsigned value in
// [0, 2^N - 1]. Results are returned in the input type T, so no narrowing conversion is implied;
// all arithmetic is done in unsigned or in ranges that cannot overflow.
#pragma once

#include <concepts>
#include <cstdint>
#include <optional>

#include "fixed/rounding.hpp"

namespace fixed {

enum class overflow {
  wrap,      // keep the low N bits (two's complement for signed)
  saturate,  // clamp to the nearest representable value
};

constexpr const char* name(overflow o) noexcept { return o == overflow::wrap ? "wrap" : "saturate"; }

enum class signedness { is_signed, is_unsigned };

// The bounds of an N-bit integer, as 64-bit values (N in 1..63).
template <int N, signedness S>
struct bit_range {
  static_assert(N >= 1 && N <= 63, "widths from 1 to 63 bits");
  static constexpr std::int64_t min = S == signedness::is_signed ? -(std::int64_t{1} << (N - 1)) : 0;
  // 2^N - 1 is formed as (2^(N-1) - 1) + 2^(N-1) so that N = 63 does not overflow.
  static constexpr std::int64_t max = S == signedness::is_signed
                                          ? (std::int64_t{1} << (N - 1)) - 1
                                          : ((std::int64_t{1} << (N - 1)) - 1) + (std::int64_t{1} << (N - 1));
  template <std::integral T>
  static constexpr bool contains(T v) noexcept {
    if constexpr (std::is_signed_v<T>) {
      return static_cast<std::int64_t>(v) >= min && static_cast<std::int64_t>(v) <= max;
    } else {
      return static_cast<std::uint64_t>(v) <= static_cast<std::uint64_t>(max);
    }
  }
};

// Keeps the low N bits of v, read as an N-bit signed or unsigned number. Requires that the
// N-bit range fits T (checked at compile time).
template <int N, signedness S, std::integral T>
constexpr T wrap(T v) noexcept {
  static_assert(N >= 1, "widths from 1 bit");
  static_assert(N < width_v<T> || (N == width_v<T> && (S == signedness::is_signed) == std::is_signed_v<T>),
                "the N-bit range must fit the type");
  static_assert(S == signedness::is_unsigned || std::is_signed_v<T>, "a signed result needs a signed type");
  using U = std::make_unsigned_t<T>;
  if constexpr (N >= width_v<T>) {
    return v;
  } else {
    const U low = static_cast<U>(static_cast<U>(v) & static_cast<U>((U{1} << N) - 1U));
    if constexpr (S == signedness::is_signed) {
      const U sign = static_cast<U>(U{1} << (N - 1));
      // (low ^ sign) - sign sign-extends an N-bit pattern; done in 64-bit signed, never overflows.
      return static_cast<T>(static_cast<std::int64_t>(low ^ sign) - static_cast<std::int64_t>(sign));
    } else {
      return static_cast<T>(low);
    }
  }
}

template <int N, signedness S, std::integral T>
constexpr T saturate(T v) noexcept {
  using R = bit_range<N, S>;
  if constexpr (std::is_signed_v<T>) {
    if (static_cast<std::int64_t>(v) < R::min) return static_cast<T>(R::min);
    if (static_cast<std::int64_t>(v) > R::max) return static_cast<T>(R::max);
  } else {
    if (static_cast<std::uint64_t>(v) > static_cast<std::uint64_t>(R::max)) return static_cast<T>(R::max);
  }
  return v;
}

// Overflow reported as an empty optional, never by undefined behaviour.
template <int N, signedness S, std::integral T>
constexpr std::optional<T> checked(T v) noexcept {
  if (bit_range<N, S>::contains(v)) return v;
  return std::nullopt;
}

template <int N, signedness S, overflow O, std::integral T>
constexpr T narrow(T v) noexcept {
  if constexpr (O == overflow::wrap) {
    return wrap<N, S>(v);
  } else {
    return saturate<N, S>(v);
  }
}

// Runtime-selected overflow, for the GS COLCLAMP register.
template <int N, signedness S, std::integral T>
constexpr T narrow(T v, overflow o) noexcept {
  return o == overflow::wrap ? wrap<N, S>(v) : saturate<N, S>(v);
}

}  // namespace fixed
