// fuzz/fixed_ops_integer.cpp — fixed_ops harness, part: integer<N, S> (see fixed_ops.cpp).
#include "fixed_ops.hpp"

namespace gsdot3::fuzz::fixed_ops {
namespace {

// ---- integer<N, S> ------------------------------------------------------------------------------
using unary_widths = std::integer_sequence<int, 1, 2, 7, 8, 9, 11, 17, 31, 33, 62>;
using binary_widths = std::integer_sequence<int, 1, 3, 8, 9, 11, 17, 24, 30>;  // sums and products fit 62
using narrow_targets = std::integer_sequence<int, 1, 8, 17, 62>;

template <int N, signedness S>
void check_integer_construction(std::int64_t x, std::uint64_t ux) {
  using I = fixed::integer<N, S>;
  constexpr bool sg = is_signed(S);
  expect(I::min_value, range_min(N, sg), [&] { return int_name(N, S) + "::min_value"; });
  expect(I::max_value, range_max(N, sg), [&] { return int_name(N, S) + "::max_value"; });
  auto each_source = [&](auto v) {
    auto call = [&](std::string_view fn) { return cat({int_name(N, S), "::", fn, "(", hex128(v), ")"}); };
    expect(I::from_wrapped(v).value(), wrap_ref(v, N, sg), [&] { return call("from_wrapped"); });
    expect(I::from_saturated(v).value(), saturate_ref(v, N, sg), [&] { return call("from_saturated"); });
    const auto c = I::from_checked(v);
    const bool in_range = v >= range_min(N, sg) && v <= range_max(N, sg);
    require(c.has_value() == in_range && (!c || i128{c->value()} == i128{v}), [&] { return call("from_checked"); });
  };
  each_source(x);
  each_source(ux);
}

template <int N, signedness S>
void check_integer_conversions(fixed::integer<N, S> v) {
  auto arg = [&] { return cat({"(", int_name(N, S), " ", hex128(v.value()), ")"}); };
  for_each_int(narrow_targets{}, [&](auto mc) {
    constexpr int M = decltype(mc)::value;
    for_each_signedness([&](auto tc) {
      constexpr signedness T = decltype(tc)::value;
      for_each_overflow([&](auto oc) {
        constexpr overflow O = decltype(oc)::value;
        expect(v.template narrow<M, T, O>().value(), narrow_ref(v.value(), M, is_signed(T), O), [&] {
          return cat({"narrow<", int_name(M, T), ",", fixed::name(O), ">", arg()});
        });
      });
      // Implicit widening exists exactly when the target range contains the source range.
      constexpr bool contains = range_min(M, is_signed(T)) <= range_min(N, is_signed(S)) &&
                                range_max(M, is_signed(T)) >= range_max(N, is_signed(S));
      static_assert(std::is_convertible_v<fixed::integer<N, S>, fixed::integer<M, T>> == contains);
      if constexpr (contains) {
        expect(static_cast<fixed::integer<M, T>>(v).value(), v.value(),
               [&] { return "widen to " + int_name(M, T) + arg(); });
      }
    });
  });
}

template <int N, signedness S>
void check_integer_shifts(fixed::integer<N, S> v) {
  for_each_int(std::integer_sequence<int, 0, 1, N / 2, N - 1>{}, [&](auto kc) {
    constexpr int K = decltype(kc)::value;
    if constexpr (K < N) {
      for_each_rounding([&](auto rc) {
        constexpr rounding R = decltype(rc)::value;
        auto what = [&](std::string_view form) {
          return cat({"shift_right<", fixed::name(R), ",", std::to_string(K), ">(", int_name(N, S), " ",
                      hex128(v.value()), ")", form});
        };
        const i128 want = exact_shift(v.value(), K, R);
        expect(fixed::shift_right<R, K>(v).value(), want, [&] { return what(""); });
        expect(fixed::shift_right<K>(v, R).value(), want, [&] { return what(" [run-time rounding]"); });
      });
    }
  });
}

template <int N, signedness S>
void check_integer_unary(FuzzedDataProvider& in) {
  const auto x = in.ConsumeIntegral<std::int64_t>();
  const auto ux = in.ConsumeIntegral<std::uint64_t>();
  check_integer_construction<N, S>(x, ux);
  const auto v = fixed::integer<N, S>::from_wrapped(x);
  check_integer_conversions(v);
  check_integer_shifts(v);
}

template <int A, signedness SA, int B, signedness SB>
void check_integer_binary(fixed::integer<A, SA> a, fixed::integer<B, SB> b) {
  auto what = [&](std::string_view op) {
    return cat({op, "(", int_name(A, SA), " ", hex128(a.value()), ", ", int_name(B, SB), " ", hex128(b.value()), ")"});
  };
  const i128 x = a.value(), y = b.value();
  expect((a + b).value(), x + y, [&] { return what("add"); });
  expect((a - b).value(), x - y, [&] { return what("sub"); });
  expect((a * b).value(), x * y, [&] { return what("mul"); });
  static_assert(decltype(a - b)::is_signed, "a difference is signed");
}

template <int A, signedness SA, int B, signedness SB>
void check_integer_binary(FuzzedDataProvider& in) {
  using IA = fixed::integer<A, SA>;
  using IB = fixed::integer<B, SB>;
  check_integer_binary(IA::from_wrapped(in.ConsumeIntegral<std::int64_t>()),
                       IB::from_wrapped(in.ConsumeIntegral<std::int64_t>()));
  // The corners of both ranges, where the widened result types are tight.
  for (auto a : {IA::from_wrapped(IA::min_value), IA::from_wrapped(IA::max_value)}) {
    for (auto b : {IB::from_wrapped(IB::min_value), IB::from_wrapped(IB::max_value)}) check_integer_binary(a, b);
  }
}

template <typename F>
void pick_signedness(FuzzedDataProvider& in, F&& f) {
  if (in.ConsumeBool()) {
    f(std::integral_constant<signedness, signedness::is_signed>{});
  } else {
    f(std::integral_constant<signedness, signedness::is_unsigned>{});
  }
}

}  // namespace

void check_integer(FuzzedDataProvider& in) {
  if (in.ConsumeBool()) {
    pick_int(unary_widths{}, in.ConsumeIntegralInRange<std::size_t>(0, unary_widths::size() - 1), [&](auto nc) {
      pick_signedness(in, [&](auto sc) { check_integer_unary<decltype(nc)::value, decltype(sc)::value>(in); });
    });
    return;
  }
  const auto ia = in.ConsumeIntegralInRange<std::size_t>(0, binary_widths::size() - 1);
  const auto ib = in.ConsumeIntegralInRange<std::size_t>(0, binary_widths::size() - 1);
  pick_int(binary_widths{}, ia, [&](auto ac) {
    pick_int(binary_widths{}, ib, [&](auto bc) {
      pick_signedness(in, [&](auto sac) {
        pick_signedness(in, [&](auto sbc) {
          check_integer_binary<decltype(ac)::value, decltype(sac)::value, decltype(bc)::value, decltype(sbc)::value>(
              in);
        });
      });
    });
  });
}

}  // namespace gsdot3::fuzz::fixed_ops
