// pipeline/scheme_normal_encoding.hpp — seed 002 in the report: the scene's normal map stored in an
// encoding (each palette normal encoded at 2×8 / 3×8 and decoded in double, nearest texel), lit as
// the float reference is; and the seed's PSNR measure on the scene's per-pixel view-space normals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scene.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {

// Render functions of the scheme_methods() rows enc-xyz, enc-xy, enc-spheremap, enc-stereographic,
// enc-octahedral (the method named after "enc-" in normal_encoding::methods()).
scheme_frame render_enc_xyz(const scene&, const prepared_scene&, const std::vector<std::int32_t>&, const render_options&);
scheme_frame render_enc_xy(const scene&, const prepared_scene&, const std::vector<std::int32_t>&, const render_options&);
scheme_frame render_enc_spheremap(const scene&, const prepared_scene&, const std::vector<std::int32_t>&, const render_options&);
scheme_frame render_enc_stereographic(const scene&, const prepared_scene&, const std::vector<std::int32_t>&, const render_options&);
scheme_frame render_enc_octahedral(const scene&, const prepared_scene&, const std::vector<std::int32_t>&, const render_options&);

// The seed's quality measure: per covered pixel, n1 = the unit view-space normal (normal-map texel
// through the barycentrically interpolated vertex frame, then the camera's rotation), n2 = its
// decode; MSE over pixels and the 3 channels of |n1 − n2| (each clamped to 1, as an image holds it),
// PSNR = −10·log10(MSE). "2009": the encoder gets the interpolated vector as is (not unit), as the
// seed's shaders did; "2010": normalised first.
struct psnr_row {
  std::string method;
  double psnr_2009 = 0, psnr_2010 = 0;
  std::size_t pixels = 0, nan_2009 = 0, nan_2010 = 0;  // NaN decodes count as error 1 per channel
  double mean_input_length = 0;                      // of the 2009 input vectors
};
std::vector<psnr_row> normal_encoding_psnr(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible, int bits);

}  // namespace gsdot3::pipeline
