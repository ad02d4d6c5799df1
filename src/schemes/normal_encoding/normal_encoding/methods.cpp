#include "normal_encoding/methods.hpp"

#include <stdexcept>
#include <string>

#include "normal_encoding/cryengine3.hpp"
#include "normal_encoding/octahedral.hpp"
#include "normal_encoding/spherical.hpp"
#include "normal_encoding/spherical_lut.hpp"
#include "normal_encoding/spheremap.hpp"
#include "normal_encoding/stereographic.hpp"
#include "normal_encoding/view_space.hpp"
#include "normal_encoding/xy.hpp"
#include "normal_encoding/xyz.hpp"

namespace gsdot3::normal_encoding {

namespace {
// #8 in the table: the view straight down −z (the frame is then the identity); view_space.hpp takes any view.
constexpr vec3 straight_view{0, 0, -1};
code view_space_encode(vec3 n, int bits) { return view_space::encode(n, straight_view, bits); }
vec3 view_space_decode(code q, int bits) { return view_space::decode(q, straight_view, bits); }
}  // namespace

const std::vector<method>& methods() {
  using M = method_id;
  static const std::vector<method> rows = {
      {M::xyz, "xyz", "baseline (2009, 2010)", 3, false, false, xyz::encode, xyz::decode},
      {M::xy, "xy", "#1 (2009, 2010)", 2, false, false, xy::encode, xy::decode},
      {M::xy_sign, "xy-sign", "#2 (2009, TODO in the seed)", 2, false, false, xy::encode_signed, xy::decode_signed},
      {M::spherical, "spherical", "#3 (2009, 2010)", 2, false, false, spherical::encode, spherical::decode},
      {M::spherical_lut, "spherical-lut", "#3a (2009)", 2, true, false, spherical_lut::encode, spherical_lut::decode},
      {M::spheremap, "spheremap", "#4 (2009)", 2, false, false, spheremap::encode, spheremap::decode},
      {M::cryengine3, "cryengine3", "#5 (2009)", 2, false, false, cryengine3::encode, cryengine3::decode},
      {M::lambert, "lambert", "#6 (2009) = #4 (2010)", 2, false, false, lambert::encode, lambert::decode},
      {M::stereographic, "stereographic", "#7 (2009, 2010)", 2, false, false, stereographic::encode,
       stereographic::decode},
      {M::view_space, "view-space", "#8 (2010)", 2, false, true, view_space_encode, view_space_decode},
      {M::octahedral, "octahedral", "not in the seed (unorm, nearest)", 2, false, false, octahedral::encode,
       octahedral::decode},
      {M::octahedral_precise, "octahedral-precise", "not in the seed (unorm, best of 4)", 2, false, false,
       octahedral::encode_precise, octahedral::decode},
      {M::octahedral_snorm, "octahedral-snorm", "not in the seed (snorm, nearest)", 2, false, false,
       octahedral::encode_snorm, octahedral::decode_snorm},
  };
  return rows;
}

const method& method_of(method_id id) {
  for (const auto& m : methods())
    if (m.id == id) return m;
  throw std::logic_error("normal_encoding: unknown method id");
}

const method& method_named(std::string_view name) {
  for (const auto& m : methods())
    if (m.name == name) return m;
  throw std::invalid_argument("normal_encoding: unknown method '" + std::string(name) + "'");
}

void check_bits(const method& m, int bits) {
  normal_encoding::check_bits(bits);
  if (m.only_8_bits && bits != 8)
    throw std::invalid_argument("normal_encoding: " + std::string(m.name) + " exists only at 8 bits, not " +
                                std::to_string(bits));
}

std::uint64_t code_count(const method& m, int bits) {
  check_bits(m, bits);
  const std::uint64_t per = std::uint64_t{1} << bits;
  if (m.channels == 3) return per * per * per;
  return per * per * (m.id == method_id::xy_sign ? 2 : 1);
}

}  // namespace gsdot3::normal_encoding
