// fuzz/fixed_ops.hpp — shared parts of the fixed_ops harness (fixed_ops*.cpp): compile-time
// iteration over types and values, names for reports, and expect(). The harness is split into three
// translation units (built-in integers, integer<N, S>, fixed_point) to keep each one's compile cheap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include <fuzzer/FuzzedDataProvider.h>

#include "fixed/fixed.hpp"
#include "fuzz_check.hpp"
#include "wide_reference.hpp"

namespace gsdot3::fuzz::fixed_ops {

using fixed::overflow;
using fixed::rounding;
using fixed::signedness;

// One operation of each family, its operands drawn from `in`.
void check_builtin(FuzzedDataProvider& in);
void check_integer(FuzzedDataProvider& in);
void check_fixed_point(FuzzedDataProvider& in);

// ---- compile-time iteration and run-time selection over lists of types and values ----------------
template <typename... T>
struct type_list {};

template <typename... T, typename F>
void for_each_type(type_list<T...>, F&& f) {
  (f(std::type_identity<T>{}), ...);
}
template <typename... T, typename F>
void pick_type(type_list<T...>, std::size_t index, F&& f) {
  std::size_t i = 0;
  ((i++ == index ? f(std::type_identity<T>{}) : void()), ...);
}
template <int... V, typename F>
void for_each_int(std::integer_sequence<int, V...>, F&& f) {
  (f(std::integral_constant<int, V>{}), ...);
}
template <int... V, typename F>
void pick_int(std::integer_sequence<int, V...>, std::size_t index, F&& f) {
  std::size_t i = 0;
  ((i++ == index ? f(std::integral_constant<int, V>{}) : void()), ...);
}
template <typename F>
void for_each_rounding(F&& f) {
  f(std::integral_constant<rounding, rounding::floor>{});
  f(std::integral_constant<rounding, rounding::toward_zero>{});
  f(std::integral_constant<rounding, rounding::nearest_ties_up>{});
  f(std::integral_constant<rounding, rounding::nearest_ties_even>{});
}
template <typename F>
void for_each_overflow(F&& f) {
  f(std::integral_constant<overflow, overflow::wrap>{});
  f(std::integral_constant<overflow, overflow::saturate>{});
}
template <typename F>
void for_each_signedness(F&& f) {
  f(std::integral_constant<signedness, signedness::is_signed>{});
  f(std::integral_constant<signedness, signedness::is_unsigned>{});
}

inline constexpr bool is_signed(signedness s) { return s == signedness::is_signed; }

template <typename T>
std::string type_name() {
  return std::string(std::is_signed_v<T> ? "int" : "uint") + std::to_string(fixed::width_v<T>);
}
// "s9", "u8".
std::string int_name(int n, signedness s);
template <typename Rep, int F>
std::string format_name(std::type_identity<fixed::fixed_point<Rep, F>>) {
  return "fixed_point<" + type_name<Rep>() + "," + std::to_string(F) + ">";
}
template <typename X>
std::string format_name() {
  return format_name(std::type_identity<X>{});
}

// The parts of a report joined (out of line: the templates only build it on a finding).
std::string cat(std::initializer_list<std::string_view> parts);

[[noreturn, gnu::cold]] void mismatch(i128 got, i128 want, const std::string& what);
// describe() names the operation and its operands; it runs only on a finding.
template <typename Describe>
[[gnu::always_inline]] inline void expect(i128 got, i128 want, Describe&& describe) {
  if (got != want) [[unlikely]]
    mismatch(got, want, describe());
}

}  // namespace gsdot3::fuzz::fixed_ops
