// normal_encoding/two_channel.hpp — a method whose encoder gives two values in [0, 1], stored as two
// unorm channels (quantise.hpp): its code and the decode of a code, from the method's own enc / dec.
#pragma once

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding {

template <void (*Enc)(vec3, double&, double&)>
code unorm2_encode(vec3 n, int bits) {
  check_bits(bits);
  double ex, ey;
  Enc(n, ex, ey);
  return {{unorm_encode(ex, bits), unorm_encode(ey, bits), 0}};
}

template <vec3 (*Dec)(double, double)>
vec3 unorm2_decode(code q, int bits) {
  check_bits(bits);
  return Dec(unorm_decode(q.c[0], bits), unorm_decode(q.c[1], bits));
}

}  // namespace gsdot3::normal_encoding
