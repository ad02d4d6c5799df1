// fixed/ios.hpp — printing that shows the value and the raw bits, e.g. "1.5 [raw 0xc0]".
#pragma once

#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

#include "fixed/fixed_point.hpp"
#include "fixed/integer.hpp"

namespace fixed {

// The raw bits of v as width_v<T> / 4 hex digits (two's complement for negatives).
template <std::integral T>
std::string hex(T v, int digits = (width_v<T> + 3) / 4) {
  std::ostringstream os;
  os << "0x" << std::hex << std::setw(digits) << std::setfill('0')
     << static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(v));
  return os.str();
}

template <std::integral Rep, int F>
std::ostream& operator<<(std::ostream& os, fixed_point<Rep, F> v) {
  std::ostringstream value;
  value << std::setprecision(17) << v.to_double();
  return os << value.str() << " [raw " << hex(v.raw()) << "]";
}

template <int N, signedness S>
std::ostream& operator<<(std::ostream& os, integer<N, S> v) {
  const auto bits = static_cast<std::uint64_t>(v.value()) & ((std::uint64_t{1} << N) - 1U);
  std::ostringstream h;
  h << "0x" << std::hex << std::setw((N + 3) / 4) << std::setfill('0') << bits;
  return os << v.value() << " [" << (S == signedness::is_signed ? "s" : "u") << N << " " << h.str() << "]";
}

}  // namespace fixed
