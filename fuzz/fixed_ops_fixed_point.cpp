// fuzz/fixed_ops_fixed_point.cpp — fixed_ops harness, part: fixed_point<Rep, F> (see fixed_ops.cpp).
#include <bit>
#include <cmath>
#include <optional>

#include "fixed_ops.hpp"

namespace gsdot3::fuzz::fixed_ops {
namespace {

// ---- fixed_point<Rep, F> ------------------------------------------------------------------------
using formats = type_list<fixed::fixed_point<std::uint8_t, 7>, fixed::fixed_point<std::int8_t, 3>,
                          fixed::fixed_point<std::uint16_t, 15>, fixed::fixed_point<std::int32_t, 7>,
                          fixed::fixed_point<std::int32_t, 31>, fixed::fixed_point<std::uint32_t, 0>>;
constexpr std::size_t format_count = 6;
using product_formats = type_list<fixed::fixed_point<std::uint8_t, 7>, fixed::fixed_point<std::int32_t, 7>,
                                  fixed::fixed_point<std::uint32_t, 16>>;

template <typename X>
constexpr int width_of = fixed::width_v<typename X::rep>;
template <typename X>
constexpr bool signed_of = std::is_signed_v<typename X::rep>;

// d · 2^F rounded as r and narrowed as o, from d's exact binary expansion; nullopt for NaN, and for
// ±infinity under wrap.
std::optional<i128> from_double_ref(double d, int f, int w, bool sg, rounding r, overflow o) {
  if (std::isnan(d)) return std::nullopt;
  if (std::isinf(d)) {
    if (o == overflow::wrap) return std::nullopt;
    return d < 0 ? range_min(w, sg) : range_max(w, sg);
  }
  int e = 0;
  const double m = std::frexp(d, &e);                                  // d = m · 2^e, 0.5 <= |m| < 1
  const auto mantissa = static_cast<std::int64_t>(std::ldexp(m, 53));  // exact: 53 significant bits
  const int s = e - 53 + f;                                            // d · 2^F = mantissa · 2^s
  i128 x = 0;
  if (s < 0) {
    x = exact_shift(mantissa, -s, r);
  } else if (s <= 60) {
    x = i128{mantissa} * pow2(s);
  } else {  // |d · 2^F| >= 2^60: beyond every 32-bit range, and a multiple of 2^61 (wraps to 0)
    if (o == overflow::wrap) return 0;
    return mantissa < 0 ? range_min(w, sg) : range_max(w, sg);
  }
  return narrow_ref(x, w, sg, o);
}

template <typename X>
void check_from_integer(FuzzedDataProvider& in) {
  using Rep = typename X::rep;
  constexpr int F = X::fraction_bits;
  auto each_source = [&](auto v) {
    for_each_overflow([&](auto oc) {
      constexpr overflow O = decltype(oc)::value;
      expect(X::template from_integer<O>(v).raw(), narrow_ref(i128{v} * pow2(F), width_of<X>, signed_of<X>, O), [&] {
        return cat(
            {format_name<X>(), "::from_integer<", fixed::name(O), ">(", type_name<decltype(v)>(), " ", hex128(v), ")"});
      });
    });
  };
  each_source(in.ConsumeIntegral<std::int64_t>());
  each_source(in.ConsumeIntegral<std::uint64_t>());
  each_source(in.ConsumeIntegral<std::int32_t>());
  each_source(in.ConsumeIntegral<Rep>());
}

template <typename X>
void check_from_double(FuzzedDataProvider& in) {
  constexpr int F = X::fraction_bits;
  // Half the time any bit pattern (NaN, infinities, subnormals), half the time n / 2^k (ties).
  const double d = in.ConsumeBool() ? std::bit_cast<double>(in.ConsumeIntegral<std::uint64_t>())
                                    : std::ldexp(static_cast<double>(in.ConsumeIntegral<std::int64_t>()),
                                                 -in.ConsumeIntegralInRange<int>(0, 70));
  for_each_rounding([&](auto rc) {
    constexpr rounding R = decltype(rc)::value;
    for_each_overflow([&](auto oc) {
      constexpr overflow O = decltype(oc)::value;
      const auto got = X::template from_double<R, O>(d);
      const auto want = from_double_ref(d, F, width_of<X>, signed_of<X>, R, O);
      auto what = [&] {
        return cat({format_name<X>(), "::from_double<", fixed::name(R), ",", fixed::name(O), ">(bits ",
                    hex128(std::bit_cast<std::uint64_t>(d)), ")"});
      };
      require(got.has_value() == want.has_value(), [&] { return what() + ": wrong presence"; });
      if (got) expect(got->raw(), *want, [&] { return what(); });
    });
  });
}

template <typename X>
void check_same_format(FuzzedDataProvider& in) {
  using Rep = typename X::rep;
  constexpr int F = X::fraction_bits;
  const auto a = X::from_raw(in.ConsumeIntegral<Rep>());
  const auto b = X::from_raw(in.ConsumeIntegral<Rep>());
  const double want_double = std::ldexp(static_cast<double>(a.raw()), -F);  // exact: at most 32 bits
  require(std::bit_cast<std::uint64_t>(a.to_double()) == std::bit_cast<std::uint64_t>(want_double), [&] {
    return cat({format_name<X>(), "::to_double(", hex128(a.raw()), ")"});
  });
  for_each_overflow([&](auto oc) {
    constexpr overflow O = decltype(oc)::value;
    auto what = [&](std::string_view op) {
      return cat({format_name<X>(), " ", op, "<", fixed::name(O), ">(", hex128(a.raw()), ", ", hex128(b.raw()), ")"});
    };
    expect(fixed::add<O>(a, b).raw(), narrow_ref(i128{a.raw()} + b.raw(), width_of<X>, signed_of<X>, O),
           [&] { return what("add"); });
    expect(fixed::sub<O>(a, b).raw(), narrow_ref(i128{a.raw()} - b.raw(), width_of<X>, signed_of<X>, O),
           [&] { return what("sub"); });
  });
  for_each_type(formats{}, [&](auto yc) {
    using Y = typename decltype(yc)::type;
    constexpr int F2 = Y::fraction_bits;
    for_each_rounding([&](auto rc) {
      constexpr rounding R = decltype(rc)::value;
      const i128 scaled = F2 >= F ? i128{a.raw()} * pow2(F2 - F) : exact_shift(a.raw(), F - F2, R);
      for_each_overflow([&](auto oc) {
        constexpr overflow O = decltype(oc)::value;
        expect(a.template convert<R, O, typename Y::rep, F2>().raw(), narrow_ref(scaled, width_of<Y>, signed_of<Y>, O),
               [&] {
                 return cat({format_name<X>(), "::convert<", fixed::name(R), ",", fixed::name(O), ",", format_name<Y>(),
                             ">(", hex128(a.raw()), ")"});
               });
      });
    });
  });
}

template <typename X, typename Y>
void check_mul(FuzzedDataProvider& in) {
  const auto a = X::from_raw(in.ConsumeIntegral<typename X::rep>());
  const auto b = Y::from_raw(in.ConsumeIntegral<typename Y::rep>());
  const i128 product = i128{a.raw()} * b.raw();
  for_each_type(product_formats{}, [&](auto zc) {
    using Z = typename decltype(zc)::type;
    constexpr int shift = X::fraction_bits + Y::fraction_bits - Z::fraction_bits;
    if constexpr (shift >= 0) {
      for_each_rounding([&](auto rc) {
        constexpr rounding R = decltype(rc)::value;
        for_each_overflow([&](auto oc) {
          constexpr overflow O = decltype(oc)::value;
          expect(
              fixed::mul<R, O, typename Z::rep, Z::fraction_bits>(a, b).raw(),
              narrow_ref(exact_shift(product, shift, R), width_of<Z>, signed_of<Z>, O), [&] {
                return cat({"mul<", fixed::name(R), ",", fixed::name(O), ",", format_name<Z>(), ">(", format_name<X>(),
                            " ", hex128(a.raw()), ", ", format_name<Y>(), " ", hex128(b.raw()), ")"});
              });
        });
      });
    }
  });
}

}  // namespace

void check_fixed_point(FuzzedDataProvider& in) {
  const auto op = in.ConsumeIntegralInRange<int>(0, 3);
  const auto ix = in.ConsumeIntegralInRange<std::size_t>(0, format_count - 1);
  pick_type(formats{}, ix, [&](auto xc) {
    using X = typename decltype(xc)::type;
    switch (op) {
      case 0: check_from_integer<X>(in); break;
      case 1: check_from_double<X>(in); break;
      case 2: check_same_format<X>(in); break;
      default:
        pick_type(formats{}, in.ConsumeIntegralInRange<std::size_t>(0, format_count - 1),
                  [&](auto yc) { check_mul<X, typename decltype(yc)::type>(in); });
    }
  });
}

}  // namespace gsdot3::fuzz::fixed_ops
