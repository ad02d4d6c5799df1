// gs_arith/field_reader.hpp — the fields of a 64-bit GS register value, for the strict decoders and
// the encoders of gs_arith/registers.cpp and gs_memory/memory_registers.cpp: each field taken by its
// low bit and width as the GS manual lays the register out, every bit outside the fields checked to
// be 0 (the field tables are gs_regs/drawing.hpp's), errors (gs::register_error) naming the register, the field and the
// value in hex.
#pragma once

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fixed/integer.hpp"
#include "gs_arith/registers.hpp"
#include "gs_regs/field.hpp"

namespace gs {

// Reads fields in order from a register value; done() checks that no bit outside the fields is set.
class field_reader {
 public:
  field_reader(std::string_view reg, std::uint64_t v) : reg_(reg), v_(v) {}
  std::uint64_t take(regs::field f) {
    used_ |= regs::mask(f);
    return regs::decode(f, v_);
  }
  bool bit(regs::field f) { return take(f) != 0; }
  // A field of width N as its fixed-width type (N is the table's width: a mismatch is a coding error).
  template <int N>
  fixed::uint<N> uint(regs::field f) {
    if (f.width != N) throw std::logic_error("field_reader::uint: width differs from the field table's");
    return fixed::uint<N>::from_wrapped(take(f));
  }
  [[noreturn]] void fail(std::string_view field, std::uint64_t value, std::string_view why) const {
    throw register_error(std::string(reg_) + "." + std::string(field) + " = " + hex(value) + ": " + std::string(why));
  }
  void done() const {
    if ((v_ & ~used_) != 0)
      throw register_error(std::string(reg_) + " = " + hex(v_) + ": reserved bits " + hex(v_ & ~used_) + " must be 0");
  }

 private:
  static std::string hex(std::uint64_t v) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(v));
    return buf;
  }
  std::string_view reg_;
  std::uint64_t v_;
  std::uint64_t used_ = 0;
};

// A field's value as the bits an encoder shifts into place (`using field_bits::bits;`).
namespace field_bits {
template <typename E>
std::uint64_t bits(E e) {
  return static_cast<std::uint64_t>(e);
}
inline std::uint64_t bits(bool b) { return b ? 1 : 0; }
template <int N>
std::uint64_t bits(fixed::uint<N> v) {
  return static_cast<std::uint64_t>(v.value());
}
}  // namespace field_bits

// A register value's field from the table: regs::encode of the field's bits.
template <typename T>
std::uint64_t place(regs::field f, T v) {
  return regs::encode(f, field_bits::bits(v));
}

}  // namespace gs
