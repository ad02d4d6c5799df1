// Uses the installed fixed headers at compile time (static_assert) and at run time.
#include <fixed/fixed.hpp>

#include <iostream>

namespace {

// The GS blend term (A - B) * C >> 7 with its datapath widths: u8 - u8 -> s9, s9 * u8 -> s17, >> 7 -> s10.
constexpr fixed::s10 blend_term(fixed::u8 a, fixed::u8 b, fixed::u8 c) {
  return fixed::shift_right<fixed::rounding::floor, 7>((a - b) * c);
}

// (0 - 255) * 128 / 128 = -255 exactly; (255 - 0) * 255 / 128 = 508.0078 -> 508.
static_assert(blend_term(fixed::u8::literal(0), fixed::u8::literal(255), fixed::u8::literal(128)).value() == -255);
static_assert(blend_term(fixed::u8::literal(255), fixed::u8::literal(0), fixed::u8::literal(255)).value() == 508);

}  // namespace

int main(int argc, char**) {
  // Operands that depend on argc (1 when run without arguments), so nothing is folded at compile time.
  const auto a = fixed::u8::from_saturated(250 + 5 * argc);  // 255
  const auto c = fixed::u8::from_saturated(254 + argc);      // 255
  const fixed::s10 t = blend_term(a, fixed::u8::literal(0), c);
  const auto colour = fixed::gs_colour::from_raw(static_cast<std::uint8_t>(0x7f + argc));  // 0x80 = 1.0
  std::cout << "blend term " << t << ", colour " << colour << "\n";
  const bool ok = t.value() == 508 && colour.to_double() == 1.0;
  std::cout << (ok ? "fixed consumer OK" : "fixed consumer WRONG") << "\n";
  return ok ? 0 : 1;
}
