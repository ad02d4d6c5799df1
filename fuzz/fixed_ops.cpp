// fuzz/fixed_ops.cpp — libFuzzer harness: every operation of include/fixed against the exact 128-bit
// reference of wide_reference.hpp, under every rounding and every overflow policy.
//   built-in integers: shift_right (template and run-time rounding; every shift, negative ones too),
//                      wrap / saturate / checked / narrow / bit_range for every width the type allows
//   integer<N, S>:     from_wrapped / from_saturated / from_checked, narrow<M, T, O>, widening,
//                      + - * (also at the corners of both ranges), shift_right<R, K> and run-time R
//                      (fixed_ops_integer.cpp)
//   fixed_point<R, F>: from_integer, from_double (any bit pattern), to_double, convert, add, sub, mul
//                      (fixed_ops_fixed_point.cpp)
// Any difference aborts with the operation, its operands and both results in hex.
#include "fixed_ops.hpp"

namespace gsdot3::fuzz::fixed_ops {

std::string int_name(int n, signedness s) { return (is_signed(s) ? "s" : "u") + std::to_string(n); }

std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (auto p : parts) s += p;
  return s;
}

void mismatch(i128 got, i128 want, const std::string& what) {
  fail(what + " = " + hex128(got) + ", expected " + hex128(want));
}

namespace {

using builtin_types = type_list<std::int8_t, std::int16_t, std::int32_t, std::int64_t, std::uint8_t, std::uint16_t,
                                std::uint32_t, std::uint64_t>;
constexpr std::size_t builtin_count = 8;

// ---- built-in integers --------------------------------------------------------------------------
template <typename T>
void check_builtin_shift(FuzzedDataProvider& in) {
  const T v = in.ConsumeIntegral<T>();
  const int k = in.ConsumeIntegralInRange<int>(-2, 2 * fixed::width_v<T> + 2);
  auto args = [&] { return cat({"(", type_name<T>(), " ", hex128(v), ", ", std::to_string(k), ")"}); };
  for_each_rounding([&](auto rc) {
    constexpr rounding R = decltype(rc)::value;
    const i128 want = exact_shift(v, k, R);
    expect(fixed::shift_right<R>(v, k), want, [&] { return cat({"shift_right<", fixed::name(R), ">", args()}); });
    expect(fixed::shift_right(v, k, R), want, [&] { return cat({"shift_right(..., ", fixed::name(R), ")", args()}); });
  });
}

template <typename T, signedness S, int N>
void check_builtin_narrow(T v) {
  constexpr bool sg = is_signed(S);
  auto args = [&] { return cat({"<", int_name(N, S), ">(", type_name<T>(), " ", hex128(v), ")"}); };
  const i128 lo = range_min(N, sg), hi = range_max(N, sg);
  const bool in_range = v >= lo && v <= hi;
  expect(fixed::wrap<N, S>(v), wrap_ref(v, N, sg), [&] { return "wrap" + args(); });
  expect(fixed::saturate<N, S>(v), saturate_ref(v, N, sg), [&] { return "saturate" + args(); });
  for_each_overflow([&](auto oc) {
    constexpr overflow O = decltype(oc)::value;
    const i128 want = narrow_ref(v, N, sg, O);
    expect(fixed::narrow<N, S, O>(v), want, [&] { return cat({"narrow/", fixed::name(O), args()}); });
    expect(fixed::narrow<N, S>(v, O), want, [&] { return cat({"narrow(..., ", fixed::name(O), ")", args()}); });
  });
  const auto c = fixed::checked<N, S>(v);
  require(c.has_value() == in_range && (!c || *c == v),
          [&] { return "checked" + args() + ": wrong presence or value"; });
  require(fixed::bit_range<N, S>::contains(v) == in_range, [&] { return "bit_range::contains" + args(); });
  expect(fixed::bit_range<N, S>::min, lo, [&] { return "bit_range::min" + args(); });
  expect(fixed::bit_range<N, S>::max, hi, [&] { return "bit_range::max" + args(); });
}

// Widths N (1..63, bit_range's limit) to which a T can be narrowed as signedness S.
template <typename T, signedness S>
constexpr int narrow_widths() {
  constexpr int w = fixed::width_v<T> < 63 ? fixed::width_v<T> : 63;
  if constexpr (is_signed(S)) return std::is_signed_v<T> ? w : 0;
  return std::is_signed_v<T> ? fixed::width_v<T> - 1 : w;
}

template <typename T>
void check_builtin_narrowing(FuzzedDataProvider& in) {
  const T v = in.ConsumeIntegral<T>();
  auto run = [&](auto sc) {
    constexpr signedness S = decltype(sc)::value;
    constexpr int count = narrow_widths<T, S>();
    const int n = in.ConsumeIntegralInRange<int>(1, count);
    for_each_int(std::make_integer_sequence<int, count>{}, [&](auto ic) {
      if (ic.value + 1 == n) check_builtin_narrow<T, S, decltype(ic)::value + 1>(v);
    });
  };
  if constexpr (std::is_signed_v<T>) {
    if (in.ConsumeBool()) {
      run(std::integral_constant<signedness, signedness::is_signed>{});
      return;
    }
  }
  run(std::integral_constant<signedness, signedness::is_unsigned>{});
}

}  // namespace

void check_builtin(FuzzedDataProvider& in) {
  const bool shift = in.ConsumeBool();
  pick_type(builtin_types{}, in.ConsumeIntegralInRange<std::size_t>(0, builtin_count - 1), [&](auto tc) {
    using T = typename decltype(tc)::type;
    if (shift) {
      check_builtin_shift<T>(in);
    } else {
      check_builtin_narrowing<T>(in);
    }
  });
}

}  // namespace gsdot3::fuzz::fixed_ops

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gsdot3::fuzz::fixed_ops;
  FuzzedDataProvider in(data, size);
  // Several operations per input: each draws its operands from what is left.
  for (int step = 0; step < 16 && in.remaining_bytes() > 0; ++step) {
    switch (in.ConsumeIntegralInRange<int>(0, 2)) {
      case 0: check_builtin(in); break;
      case 1: check_integer(in); break;
      default: check_fixed_point(in); break;
    }
  }
  return 0;
}
