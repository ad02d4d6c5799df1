// fixed/integer.hpp — integers that carry their bit width in the type.
//
// integer<N, S> holds a value of an N-bit signed or unsigned integer. Arithmetic widens exactly as
// far as the result's range needs, so no operation can overflow, and the widths of a hardware
// datapath can be read off the types: u8 - u8 -> s9, s9 * u8 -> s17, s17 >> 7 -> s10, s10 + u8 -> s11.
// Narrowing back (to the 8 bits of a colour channel) is explicit, with a named overflow behaviour.
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <functional>
#include <optional>
#include <type_traits>

#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"

namespace fixed {

template <int N, signedness S>
class integer {
  static_assert(N >= 1 && N <= 62, "integer widths from 1 to 62 bits");

 public:
  static constexpr int bits = N;
  static constexpr bool is_signed = S == signedness::is_signed;
  using rep = std::conditional_t<(N <= 31), std::int32_t, std::int64_t>;
  using range = bit_range<N, S>;
  static constexpr rep min_value = static_cast<rep>(range::min);
  static constexpr rep max_value = static_cast<rep>(range::max);

  constexpr integer() noexcept = default;

  // Only in-range values: a compile-time error in constant evaluation, otherwise use from_wrapped,
  // from_saturated or from_checked to say what an out-of-range value means.
  static consteval integer literal(std::int64_t v) {
    if (v < range::min || v > range::max) throw "integer::literal out of range";
    return integer(static_cast<rep>(v));
  }
  template <std::integral T>
  static constexpr integer from_wrapped(T v) noexcept {
    return integer(static_cast<rep>(wrap<N, S>(static_cast<std::int64_t>(v))));
  }
  template <std::integral T>
  static constexpr integer from_saturated(T v) noexcept {
    if constexpr (std::is_unsigned_v<T>) {
      if (static_cast<std::uint64_t>(v) > static_cast<std::uint64_t>(range::max)) return integer(max_value);
      return integer(static_cast<rep>(v));
    } else {
      return integer(static_cast<rep>(saturate<N, S>(static_cast<std::int64_t>(v))));
    }
  }
  template <std::integral T>
  static constexpr std::optional<integer> from_checked(T v) noexcept {
    if (!range::contains(v)) return std::nullopt;
    return integer(static_cast<rep>(v));
  }

  constexpr rep value() const noexcept { return v_; }
  explicit constexpr operator rep() const noexcept { return v_; }

  friend constexpr bool operator==(integer, integer) noexcept = default;
  friend constexpr auto operator<=>(integer, integer) noexcept = default;

  // Widening to a type whose range contains this one's (never loses information).
  template <int M, signedness T>
  constexpr operator integer<M, T>() const noexcept
      requires(bit_range<M, T>::min <= range::min && bit_range<M, T>::max >= range::max) {
    return integer<M, T>::from_wrapped(v_);
  }

  // Narrowing to M bits with a named overflow behaviour.
  template <int M, signedness T, overflow O>
  constexpr integer<M, T> narrow() const noexcept {
    if constexpr (O == overflow::wrap) {
      return integer<M, T>::from_wrapped(v_);
    } else {
      return integer<M, T>::from_saturated(v_);
    }
  }

 private:
  explicit constexpr integer(rep v) noexcept : v_(v) {}
  template <int, signedness>
  friend class integer;
  rep v_ = 0;
};

template <int N>
using sint = integer<N, signedness::is_signed>;
template <int N>
using uint = integer<N, signedness::is_unsigned>;

using u1 = uint<1>;
using u3 = uint<3>;
using u4 = uint<4>;
using u5 = uint<5>;
using u8 = uint<8>;
using s3 = sint<3>;
using s9 = sint<9>;
using s10 = sint<10>;
using s11 = sint<11>;
using s17 = sint<17>;

namespace detail {
constexpr signedness either_signed(signedness a, signedness b) {
  return a == signedness::is_signed || b == signedness::is_signed ? signedness::is_signed : signedness::is_unsigned;
}
// Width that holds the union of two ranges.
constexpr int union_bits(int na, signedness sa, int nb, signedness sb) {
  const signedness s = either_signed(sa, sb);
  // An unsigned N-bit range needs N+1 bits when the result is signed.
  const int wa = (s == signedness::is_signed && sa == signedness::is_unsigned) ? na + 1 : na;
  const int wb = (s == signedness::is_signed && sb == signedness::is_unsigned) ? nb + 1 : nb;
  return wa > wb ? wa : wb;
}
}  // namespace detail

// a + b: the union of both ranges plus one carry bit.
template <int A, signedness SA, int B, signedness SB>
constexpr auto operator+(integer<A, SA> a, integer<B, SB> b) noexcept {
  constexpr signedness s = detail::either_signed(SA, SB);
  using R = integer<detail::union_bits(A, SA, B, SB) + 1, s>;
  return R::from_wrapped(static_cast<std::int64_t>(a.value()) + b.value());
}

// a - b: always signed; one bit above the union of the (signed) ranges.
template <int A, signedness SA, int B, signedness SB>
constexpr auto operator-(integer<A, SA> a, integer<B, SB> b) noexcept {
  constexpr int w = detail::union_bits(A, SA, B, SB);
  using R = sint<w + 1>;
  return R::from_wrapped(static_cast<std::int64_t>(a.value()) - b.value());
}

// a * b: A + B bits, signed if either operand is. (-2^(A-1))·(2^B - 1) and the other corner fit.
template <int A, signedness SA, int B, signedness SB>
constexpr auto operator*(integer<A, SA> a, integer<B, SB> b) noexcept {
  constexpr signedness s = detail::either_signed(SA, SB);
  using R = integer<A + B, s>;
  return R::from_wrapped(static_cast<std::int64_t>(a.value()) * b.value());
}

// Division by 2^K with a named rounding. Floor and truncation need N-K bits; rounding to nearest can
// round the largest value up, so it keeps one more bit (except when K = 0).
template <rounding R, int K, int N, signedness S>
constexpr auto shift_right(integer<N, S> v) noexcept {
  static_assert(K >= 0 && K < N, "shift within the width");
  constexpr bool nearest = R == rounding::nearest_ties_up || R == rounding::nearest_ties_even;
  constexpr int w = (K == 0) ? N : (nearest ? N - K + 1 : N - K);
  using Out = integer<w, S>;  // K < N, so w >= 1
  return Out::from_wrapped(fixed::shift_right<R>(static_cast<std::int64_t>(v.value()), K));
}

// Runtime-selected rounding; the result type is the widest of the four.
template <int K, int N, signedness S>
constexpr integer<(K == 0 ? N : N - K + 1), S> shift_right(integer<N, S> v, rounding r) noexcept {
  return integer<(K == 0 ? N : N - K + 1), S>::from_wrapped(
      fixed::shift_right(static_cast<std::int64_t>(v.value()), K, r));
}

}  // namespace fixed

// Hashes the value, so equal integers of one type hash equally.
template <int N, fixed::signedness S>
struct std::hash<fixed::integer<N, S>> {
  std::size_t operator()(fixed::integer<N, S> v) const noexcept {
    return std::hash<typename fixed::integer<N, S>::rep>{}(v.value());
  }
};
