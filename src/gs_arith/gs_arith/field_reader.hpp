// gs_arith/field_reader.hpp — the fields of a 64-bit GS register value, for the strict decoders and
// the encoders of gs_arith/registers.cpp and gs_memory/memory_registers.cpp: each field taken by its
// low bit and width as the GS manual lays the register out, every bit outside the fields checked to
// be 0, errors (gs::register_error) naming the register, the field and the value in hex.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "fixed/integer.hpp"
#include "gs_arith/registers.hpp"

namespace gs {

// Reads fields in order from a register value; done() checks that no bit outside the fields is set.
class field_reader {
 public:
  field_reader(std::string_view reg, std::uint64_t v) : reg_(reg), v_(v) {}
  std::uint64_t take(int lo, int width) {
    const std::uint64_t mask = width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
    used_ |= mask << lo;
    return (v_ >> lo) & mask;
  }
  bool bit(int lo) { return take(lo, 1) != 0; }
  template <int N>
  fixed::uint<N> uint(int lo) {
    return fixed::uint<N>::from_wrapped(take(lo, N));
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

}  // namespace gs
