// tests/fixed/exhaustive_test.cpp — include/fixed against the independent reference (reference.hpp)
// over whole domains. Each test counts its cases and checks the count equals the domain's size, so
// a sweep that silently skipped part of its domain fails. Mismatches print their inputs in hex.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>

#include "fixed/fixed.hpp"
#include "reference.hpp"

namespace {

using fixed::overflow;
using fixed::rounding;
using fixed::signedness;

// Counts cases and mismatches; reports the first few mismatches in full.
class sweep {
 public:
  template <class Describe>
  void check(bool ok, Describe describe) {
    ++cases_;
    if (ok) return;
    if (++mismatches_ <= 10) ADD_FAILURE() << describe();
  }
  void expect_complete(std::int64_t domain_size, const char* domain) const {
    std::cout << domain << ": " << cases_ << " cases, " << mismatches_ << " mismatches\n";
    EXPECT_EQ(mismatches_, 0) << domain;
    EXPECT_EQ(cases_, domain_size) << domain << ": the sweep did not cover its whole domain";
  }

 private:
  std::int64_t cases_ = 0;
  std::int64_t mismatches_ = 0;
};

template <class... Parts>
std::string describe(const Parts&... parts) {
  std::ostringstream os;
  (os << ... << parts);
  return os.str();
}

// Every value of T, every shift 0..max_shift, every mode, both the compile-time-mode and the
// run-time-mode overload.
template <class T>
void sweep_shift_right(sweep& s, int max_shift) {
  fixed_ref::for_each_rounding([&]<rounding R>() {
    for (std::int64_t i = std::numeric_limits<T>::min(); i <= std::numeric_limits<T>::max(); ++i) {
      const auto v = static_cast<T>(i);
      for (int k = 0; k <= max_shift; ++k) {
        const std::int64_t want = fixed_ref::divide_pow2<std::int64_t>(v, k, R);
        const T got = fixed::shift_right<R>(v, k);
        const T got_runtime = fixed::shift_right(v, k, R);
        s.check(got == want && got_runtime == want, [&] {
          return describe(fixed::name(R), " shift_right(", fixed::hex(v), ", ", k, ") = ", fixed::hex(got),
                          " (run-time mode ", fixed::hex(got_runtime), "), reference ",
                          fixed::hex(static_cast<T>(want)));
        });
      }
    }
  });
}

TEST(FixedExhaustive, ShiftRightEvery16BitInputEveryShift) {
  // Shifts 16 and 17 are >= the width of the type: the library computes them separately.
  sweep s;
  sweep_shift_right<std::int16_t>(s, 17);
  sweep_shift_right<std::uint16_t>(s, 17);
  s.expect_complete(4 * 2 * 65536 * 18, "shift_right, 4 modes x {int16_t, uint16_t} x 2^16 x k 0..17");
}

TEST(FixedExhaustive, ShiftRightEvery8BitInputEveryShift) {
  sweep s;
  sweep_shift_right<std::int8_t>(s, 9);
  sweep_shift_right<std::uint8_t>(s, 9);
  s.expect_complete(4 * 2 * 256 * 10, "shift_right, 4 modes x {int8_t, uint8_t} x 2^8 x k 0..9");
}

// wrap, saturate, checked and both narrow overloads of v to N bits, plus integer<17>::narrow.
template <int N, signedness S, class T>
void check_narrowing(sweep& s, T v) {
  constexpr bool is_signed = S == signedness::is_signed;
  const std::int64_t x = v;
  const std::int64_t want_wrap = fixed_ref::wrap<std::int64_t>(x, N, is_signed);
  const std::int64_t want_sat = fixed_ref::saturate<std::int64_t>(x, N, is_signed);
  const bool fits = fixed_ref::fits<std::int64_t>(x, N, is_signed);
  const std::int64_t w = fixed::wrap<N, S>(v);
  const std::int64_t sat = fixed::saturate<N, S>(v);
  const auto c = fixed::checked<N, S>(v);
  const bool ok = w == want_wrap && sat == want_sat && c.has_value() == fits && (!fits || *c == v) &&
                  fixed::narrow<N, S, overflow::wrap>(v) == w && fixed::narrow<N, S, overflow::saturate>(v) == sat &&
                  fixed::narrow<N, S>(v, overflow::wrap) == w && fixed::narrow<N, S>(v, overflow::saturate) == sat;
  s.check(ok, [&] {
    return describe(is_signed ? "s" : "u", N, " of ", fixed::hex(v), ": wrap ", w, " (reference ", want_wrap,
                    "), saturate ", sat, " (reference ", want_sat, "), checked ",
                    c ? std::to_string(*c) : std::string("overflow"), " (reference ", fits ? "fits" : "overflow", ")");
  });
}

template <int N, signedness S, signedness In>
void check_integer_narrowing(sweep& s, std::int64_t x) {
  constexpr bool is_signed = S == signedness::is_signed;
  const auto v = fixed::integer<17, In>::from_wrapped(x);
  const auto w = v.template narrow<N, S, overflow::wrap>();
  const auto sat = v.template narrow<N, S, overflow::saturate>();
  s.check(w.value() == fixed_ref::wrap<std::int64_t>(x, N, is_signed) &&
              sat.value() == fixed_ref::saturate<std::int64_t>(x, N, is_signed),
          [&] { return describe("integer<17>(", x, ").narrow to ", is_signed ? "s" : "u", N, ": ", w, ", ", sat); });
}

TEST(FixedExhaustive, WrapSaturateCheckedEvery17BitInput) {
  // Every 17-bit pattern p, read as signed (-2^16..2^16-1) and unsigned (0..2^17-1), narrowed to
  // s8, u8, s9, u9. Signed readings are held in int32_t; unsigned ones in int32_t and in uint32_t
  // (a uint32_t cannot be narrowed to a signed width: rejected at compile time).
  sweep s;
  for (std::int32_t p = 0; p < (1 << 17); ++p) {
    const std::int32_t as_signed = p >= (1 << 16) ? p - (1 << 17) : p;
    for (const std::int32_t v : {as_signed, p}) {
      check_narrowing<8, signedness::is_signed>(s, v);
      check_narrowing<8, signedness::is_unsigned>(s, v);
      check_narrowing<9, signedness::is_signed>(s, v);
      check_narrowing<9, signedness::is_unsigned>(s, v);
    }
    const auto u = static_cast<std::uint32_t>(p);
    check_narrowing<8, signedness::is_unsigned>(s, u);
    check_narrowing<9, signedness::is_unsigned>(s, u);
    check_integer_narrowing<8, signedness::is_signed, signedness::is_signed>(s, as_signed);
    check_integer_narrowing<8, signedness::is_unsigned, signedness::is_signed>(s, as_signed);
    check_integer_narrowing<9, signedness::is_signed, signedness::is_unsigned>(s, p);
    check_integer_narrowing<9, signedness::is_unsigned, signedness::is_unsigned>(s, p);
  }
  s.expect_complete(std::int64_t{1 << 17} * (2 * 4 + 2 + 4), "narrowing, 2^17 patterns x 14 (reading, target) pairs");
}

// f(a, b) over every pair of values of integer types A and B.
template <class A, class B, class F>
void every_pair(F f) {
  for (std::int64_t a = A::min_value; a <= A::max_value; ++a) {
    for (std::int64_t b = B::min_value; b <= B::max_value; ++b) f(A::from_wrapped(a), B::from_wrapped(b), a, b);
  }
}

template <class A, class B>
std::int64_t pairs() {
  return (std::int64_t{A::max_value} - A::min_value + 1) * (std::int64_t{B::max_value} - B::min_value + 1);
}

TEST(FixedExhaustive, IntegerArithmeticSmallDomains) {
  sweep s;
  // The result types are the datapath widths; see also the static_asserts in unit_test.cpp.
  every_pair<fixed::u8, fixed::u8>([&](auto a, auto b, std::int64_t x, std::int64_t y) {
    const fixed::s9 d = a - b;
    const fixed::uint<9> sum = a + b;
    const fixed::uint<16> p = a * b;
    s.check(d.value() == x - y && sum.value() == x + y && p.value() == x * y,
            [&] { return describe(a, " -,+,* ", b, ": ", d, ", ", sum, ", ", p); });
  });
  every_pair<fixed::s9, fixed::u8>([&](auto a, auto b, std::int64_t x, std::int64_t y) {
    const fixed::s17 p = a * b;
    const fixed::s10 d = a - b;
    s.check(p.value() == x * y && d.value() == x - y, [&] { return describe(a, " *,- ", b, ": ", p, ", ", d); });
  });
  every_pair<fixed::s10, fixed::u8>([&](auto a, auto b, std::int64_t x, std::int64_t y) {
    const fixed::s11 sum = a + b;
    s.check(sum.value() == x + y, [&] { return describe(a, " + ", b, ": ", sum); });
  });
  s.expect_complete(pairs<fixed::u8, fixed::u8>() + pairs<fixed::s9, fixed::u8>() + pairs<fixed::s10, fixed::u8>(),
                    "u8 -,+,* u8 (2^16); s9 *,- u8 (2^17); s10 + u8 (2^18)");
}

TEST(FixedExhaustive, IntegerShiftEveryS17) {
  // The GS blend's (A - B) * C >> 7 step: every s17 value, every mode, both overloads.
  sweep s;
  fixed_ref::for_each_rounding([&]<rounding R>() {
    for (std::int64_t x = fixed::s17::min_value; x <= fixed::s17::max_value; ++x) {
      const auto v = fixed::s17::from_wrapped(x);
      const auto q = fixed::shift_right<R, 7>(v);
      const fixed::s11 q_runtime = fixed::shift_right<7>(v, R);
      const std::int64_t want = fixed_ref::divide_pow2<std::int64_t>(x, 7, R);
      s.check(q.value() == want && q_runtime.value() == want, [&] {
        return describe(fixed::name(R), " s17 ", v, " >> 7: ", q, " / ", q_runtime, ", reference ", want);
      });
    }
  });
  s.expect_complete(4 * 131072, "integer shift_right<7>, 4 modes x 2^17 s17 values");
}

TEST(FixedExhaustive, IntegerConstructionAndWidening) {
  // from_wrapped / from_saturated / from_checked to s11 and u8 of every int32_t in -2^13..2^13-1,
  // and every s9 widened to s17 and to s10.
  sweep s;
  for (std::int32_t x = -(1 << 13); x < (1 << 13); ++x) {
    const auto w = fixed::s11::from_wrapped(x);
    const auto sat = fixed::u8::from_saturated(x);
    const auto c = fixed::s11::from_checked(x);
    const bool fits = fixed_ref::fits<std::int64_t>(x, 11, true);
    s.check(w.value() == fixed_ref::wrap<std::int64_t>(x, 11, true) &&
                sat.value() == fixed_ref::saturate<std::int64_t>(x, 8, false) && c.has_value() == fits &&
                (!fits || c->value() == x),
            [&] { return describe("construction from ", fixed::hex(x), ": s11 wrap ", w, ", u8 saturate ", sat); });
  }
  for (std::int64_t x = fixed::s9::min_value; x <= fixed::s9::max_value; ++x) {
    const auto v = fixed::s9::from_wrapped(x);
    const fixed::s17 wide = v;
    const fixed::s10 wider = v;
    s.check(wide.value() == x && wider.value() == x, [&] { return describe("widening ", v, ": ", wide, ", ", wider); });
  }
  s.expect_complete((1 << 14) + 512, "integer construction (2^14 inputs) and s9 widening (2^9)");
}

TEST(FixedExhaustive, GsColourProductEveryPair) {
  // gs_colour x gs_colour -> gs_colour: the exact product a·b / 2^7, every mode, both overflows.
  sweep s;
  fixed_ref::for_each_rounding([&]<rounding R>() {
    for (std::int64_t a = 0; a < 256; ++a) {
      for (std::int64_t b = 0; b < 256; ++b) {
        const auto x = fixed::gs_colour::from_raw(static_cast<std::uint8_t>(a));
        const auto y = fixed::gs_colour::from_raw(static_cast<std::uint8_t>(b));
        const std::int64_t q = fixed_ref::divide_pow2<std::int64_t>(a * b, 7, R);
        const auto w = fixed::mul<R, overflow::wrap, std::uint8_t, 7>(x, y);
        const auto sat = fixed::mul<R, overflow::saturate, std::uint8_t, 7>(x, y);
        s.check(w.raw() == fixed_ref::wrap<std::int64_t>(q, 8, false) &&
                    sat.raw() == fixed_ref::saturate<std::int64_t>(q, 8, false),
                [&] { return describe(fixed::name(R), " ", x, " * ", y, ": wrap ", w, ", saturate ", sat); });
      }
    }
  });
  s.expect_complete(4 * 65536, "gs_colour products, 4 modes x 2^16 pairs");
}

}  // namespace
