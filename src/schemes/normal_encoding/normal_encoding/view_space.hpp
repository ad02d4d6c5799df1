// normal_encoding/view_space.hpp — Method #8: per-pixel view space (2010 revision only; Yuriy
// O'Donnell). make_view_mat(view): z = −normalize(view); x = normalize((z.z, 0, −z.x)); y = cross(z, x);
// enc = (M·n).xy·0.5 + 0.5 with M's rows x, y, z; dec: n.xy = enc·2 − 1, n.z = sqrt(1 − dot(n.xy, n.xy)),
// n = Mᵀ·n. It is Method #1 in a per-pixel rotated frame, so over the hemisphere facing the viewer
// (n·view <= 0) its errors are #1's over z >= 0; a view along ±y makes x = normalize(0) = NaN.
#pragma once

#include <cmath>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"
#include "normal_encoding/xy.hpp"

namespace gsdot3::normal_encoding::view_space {

struct basis {
  vec3 x, y, z;
};
inline basis make_view_mat(vec3 view) noexcept {
  const vec3 z = -1.0 * normalize(view);
  const vec3 x = normalize(vec3{z.z, 0, -z.x});
  return {x, cross(z, x), z};
}

inline code encode(vec3 n, vec3 view, int bits) {
  const basis m = make_view_mat(view);
  return xy::encode({dot(m.x, n), dot(m.y, n), dot(m.z, n)}, bits);
}
inline vec3 decode(code q, vec3 view, int bits) {
  const basis m = make_view_mat(view);
  const vec3 v = xy::decode(q, bits);
  return v.x * m.x + v.y * m.y + v.z * m.z;
}

}  // namespace gsdot3::normal_encoding::view_space
