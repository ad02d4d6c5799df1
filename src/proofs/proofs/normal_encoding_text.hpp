// proofs/normal_encoding_text.hpp — what the seed-002 claims (claims_normal_encoding*.cpp) share:
// the constants of their domains and how a normal and a code are printed in a witness.
#pragma once

#include <cstdint>
#include <numbers>
#include <string>

#include "normal_encoding/methods.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::claims::encoding_text {

namespace ne = normal_encoding;

inline constexpr double deg = 180 / std::numbers::pi;
inline constexpr int bits8 = 8;
// The area-uniform set of the catalogue (sampling.hpp): 2^16 Fibonacci points.
inline constexpr std::uint64_t uniform_points = 65536;

// "(x, y, z) = (hex, hex, hex)": a normal in decimal and exactly.
std::string vec_text(ne::vec3 n);
// "(c0, c1)" or, for three-channel codes and #2's sign bit, "(c0, c1, c2)".
std::string code_text(const ne::method& m, ne::code q);
inline std::string name(const ne::method& m) { return std::string(m.name); }
// The methods with a rounding-cell analysis of their own (octahedral-precise is bounded by octahedral's).
inline bool cell_method(const ne::method& m) { return m.id != ne::method_id::octahedral_precise; }

}  // namespace gsdot3::proofs::claims::encoding_text
