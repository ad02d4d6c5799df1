// normal_encoding/seed_2009.hpp — seed 002's PSNR measured as the 2009 article measured it, bug included.
//
// What the 2009 pipeline gave its encoders: its 2010 header says "encoding shaders do not normalize the
// incoming per-vertex normal" — the view-space vertex normals, linearly interpolated across each
// triangle and so shorter than unit inside a face of a curved mesh, went to the 2009 encoder
// (`method::encode`, not `encode_2010`) as they were.
//
// What it compared against, read from the seed: "n1 is actual normal, and n2 is normal encoded into a
// texture, read back & decoded. MSE and PSNR is computed on the difference (abs(n1-n2)) image", and its
// baseline (xyz, which stores the vector it is given, whatever its length) has an error that "happens
// only because of quantization to 8 bits per component" at 52.661 dB — the figure of pure 8-bit
// quantisation of the vector itself (10·log10(3·255²) = 52.90 dB, seed_psnr.hpp). Had n1 been the
// normalised normal, xyz would also carry 1 − |v| on its curved faces (claim
// normal-encoding.seed-2009-measure, `xyz.psnr_vs_unit`: 37.1 dB on an 8×16 sphere, 47.5 on a 16×32 one).
// So n1 is the vector the encoder was given, v itself: `vs_given`. The other reading, n1 = normalize(v),
// is kept as `vs_unit` (what the 2010 header's "evaluation results being somewhat wrong" would fix);
// the seed's own scene is not available to settle it further.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "normal_encoding/methods.hpp"
#include "normal_encoding/seed_psnr.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding {

// The vertex normals n0, n1, n2 interpolated with the barycentric weights l0, l1, l2 (not normalised).
constexpr vec3 interpolate(vec3 n0, vec3 n1, vec3 n2, double l0, double l1, double l2) noexcept {
  return l0 * n0 + l1 * n1 + l2 * n2;
}

struct seed_2009_error {
  seed_error vs_given, vs_unit;
  double mean_length = 0;  // mean |v| of the pixels
};

// Per pixel v, the interpolated vector as the encoder received it: the 2009 encoder, the decoder, and
// the seed's difference image against v (vs_given) and against normalize(v) (vs_unit).
class seed_2009_sum {
 public:
  void add(const method& m, vec3 v, int bits) {
    const vec3 d = m.decode(m.encode(v, bits), bits);
    given_.add(v, d);
    unit_.add(normalize(v), d);
    length_ += length(v);
  }
  [[nodiscard]] seed_2009_error done() const noexcept {
    const auto n = given_.done().samples;
    return {given_.done(), unit_.done(), n > 0 ? length_ / static_cast<double>(n) : 0};
  }

 private:
  seed_error_sum given_, unit_;
  double length_ = 0;
};

// A UV sphere of `rings` latitude bands and `segments` meridians (pole fans, 2·segments·(rings − 1)
// triangles), its vertex normals the unit vertex positions, drawn orthographically from +z into a
// size × size grid of pixel centres over [−1, 1]²: per covered pixel the interpolated vertex normal of
// the front face it hits (which, the normals being the positions, is that point of the face). The
// seed's scene had spheres ("the same scenario happens on the edges of the spheres"); its tessellation
// is not stated, so this is a stand-in, swept over tessellations.
std::vector<vec3> faceted_sphere_normals(int rings, int segments, int size);

// The tessellations the claim normal-encoding.seed-2009-measure and `gsdot3 normal-encoding` draw,
// each at sphere_pixels² (coarse, medium, fine: mean |v| 0.978, 0.994, 0.9986).
struct sphere_tessellation {
  int rings, segments;
};
inline constexpr sphere_tessellation sphere_tessellations[] = {{8, 16}, {16, 32}, {32, 64}};
inline constexpr int sphere_pixels = 512;

// The seed's 2009 measure of `m` over the interpolated vectors `pixels`.
seed_2009_error measure_2009(const method& m, int bits, const std::vector<vec3>& pixels);

}  // namespace gsdot3::normal_encoding
