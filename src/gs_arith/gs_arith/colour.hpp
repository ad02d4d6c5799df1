// gs_arith/colour.hpp — colour values at the widths the GS datapath has them.
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"

namespace gs {

using fixed::s11;
using fixed::u8;

// An 8-bit-per-channel colour; as a 32-bit register or frame-buffer word it is A8B8G8R8 (R low).
struct rgba8 {
  u8 r, g, b, a;

  static constexpr rgba8 from_u32(std::uint32_t v) noexcept {
    return {u8::from_wrapped(v), u8::from_wrapped(v >> 8), u8::from_wrapped(v >> 16), u8::from_wrapped(v >> 24)};
  }
  constexpr std::uint32_t to_u32() const noexcept {
    return static_cast<std::uint32_t>(r.value()) | static_cast<std::uint32_t>(g.value()) << 8 |
           static_cast<std::uint32_t>(b.value()) << 16 | static_cast<std::uint32_t>(a.value()) << 24;
  }
  friend constexpr bool operator==(const rgba8&, const rgba8&) = default;
};

// The blender's output before COLCLAMP: each RGB channel in −509..763 (11 bits signed); alpha is As.
struct rgb_wide {
  s11 r, g, b;
  friend constexpr bool operator==(const rgb_wide&, const rgb_wide&) = default;
};

}  // namespace gs
