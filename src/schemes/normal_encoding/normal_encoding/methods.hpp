// normal_encoding/methods.hpp — the table of every encoding: name, what the seed numbers it, the
// stored code layout and its encode/decode at a bit count. The 2009 encoders take n as given (the
// seed's bug: it did not normalise interpolated normals); `encode_2010` normalises first.
#pragma once

#include <string_view>
#include <vector>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding {

enum class method_id {
  xyz,
  xy,
  xy_sign,
  spherical,
  spherical_lut,
  spheremap,
  cryengine3,
  lambert,
  stereographic,
  view_space,
  octahedral,
  octahedral_precise,
  octahedral_snorm,
};

struct method {
  method_id id;
  std::string_view name;  // e.g. "octahedral"
  std::string_view seed;  // e.g. "#4 (2009)", "2010", "not in the seed"
  int channels;           // stored channels of `bits` each (#2 adds one sign bit in channel 2)
  bool only_8_bits;       // #3a: its LUTs are 8-bit textures
  bool front_hemisphere;  // the method only claims z >= 0 (#8: the hemisphere facing the viewer)
  code (*encode)(vec3 n, int bits);
  vec3 (*decode)(code q, int bits);
};

const std::vector<method>& methods();
const method& method_of(method_id id);
// By name; std::invalid_argument (one line) for an unknown name.
const method& method_named(std::string_view name);
// Throws std::invalid_argument (one line) unless `bits` is supported for m.
void check_bits(const method& m, int bits);

inline code encode_2010(const method& m, vec3 n, int bits) { return m.encode(normalize(n), bits); }

// Codes per channel at `bits` (2^bits; #2's sign channel: 2).
std::uint64_t code_count(const method& m, int bits);

}  // namespace gsdot3::normal_encoding
