// gs_regs/field.hpp — one field of a 64-bit GS register (its manual name, low bit and width) and the
// pure functions every decoder and encoder takes its shifts and masks from: mask, decode, encode.
// A register is a list of fields (gs_regs/registers.hpp); its reserved bits are those of no field.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>

namespace gs::regs {

// A field: bits [lo, lo + width) of the register's 64-bit value, named as the GS User's Manual does.
struct field {
  std::string_view name;
  int lo;
  int width;
};

// The field's width ones, unshifted: the largest value it holds.
constexpr std::uint64_t max_value(field f) {
  return f.width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << f.width) - 1;
}

// The bits of the field in the register value.
constexpr std::uint64_t mask(field f) { return max_value(f) << f.lo; }

// The bits of all the fields of a register: the complement is the reserved bits (which must be 0).
constexpr std::uint64_t mask(std::span<const field> fields) {
  std::uint64_t m = 0;
  for (const field& f : fields) m |= mask(f);
  return m;
}

// The field's value taken out of a register value.
constexpr std::uint64_t decode(field f, std::uint64_t word) { return (word >> f.lo) & max_value(f); }

// The field's value as the narrower unsigned type T the caller stores it in (T holds the field's width).
template <typename T = std::uint32_t>
constexpr T decode_as(field f, std::uint64_t word) {
  return static_cast<T>(decode(f, word));
}

// The value placed at the field's bits; a value wider than the field is an error, not truncated.
constexpr std::uint64_t encode(field f, std::uint64_t value) {
  if (value > max_value(f)) throw std::out_of_range("GS register field too narrow for the value");
  return value << f.lo;
}

// The value's low `width` bits placed at the field (the rest dropped, as the GS drops the bits a
// narrower register field has no room for, e.g. a PACKED qword's 32-bit U in UV's 14-bit U).
constexpr std::uint64_t encode_low_bits(field f, std::uint64_t value) noexcept {
  return (value & max_value(f)) << f.lo;
}

// Whether a field's value is one the manual lists as valid (e.g. a PSM field's pixel formats).
constexpr bool is_one_of(std::uint64_t value, std::span<const std::uint64_t> valid) {
  for (const std::uint64_t v : valid)
    if (v == value) return true;
  return false;
}

}  // namespace gs::regs
