// proofs/normal_encoding_text.cpp — how the seed-002 claims print a normal and a code (see the header).
#include "proofs/normal_encoding_text.hpp"

namespace gsdot3::proofs::claims::encoding_text {

// Built by appending: GCC 12 warns (-Wrestrict, a known false positive, GCC bug 105329) on
// "(" + std::string once these are inlined.
std::string vec_text(ne::vec3 n) {
  std::string s = "(";
  s.append(real_text(n.x)).append(", ").append(real_text(n.y)).append(", ").append(real_text(n.z));
  s.append(") = (").append(hex_float(n.x)).append(", ").append(hex_float(n.y)).append(", ");
  return s.append(hex_float(n.z)).append(")");
}
std::string code_text(const ne::method& m, ne::code q) {
  std::string s = "(";
  s.append(std::to_string(q.c[0])).append(", ").append(std::to_string(q.c[1]));
  if (m.channels == 3 || m.id == ne::method_id::xy_sign) s.append(", ").append(std::to_string(q.c[2]));
  return s.append(")");
}

}  // namespace gsdot3::proofs::claims::encoding_text
