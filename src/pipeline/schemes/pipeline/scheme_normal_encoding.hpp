// pipeline/scheme_normal_encoding.hpp — seed 002 in the report: the scene's normal map stored in an
// encoding (each palette normal encoded at 2×8 / 3×8 and decoded in double, nearest texel), lit as
// the float reference is; and the seed's PSNR measure on the scene's per-pixel view-space normals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "normal_encoding/seed_2009.hpp"
#include "normal_encoding/seed_psnr.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {

// Render functions of the scheme_methods() rows enc-xyz, enc-xy, enc-spheremap, enc-stereographic,
// enc-octahedral (the method named after "enc-" in normal_encoding::methods()).
scheme_frame render_enc_xyz(const scene&, const prepared_scene&, const std::vector<std::int32_t>&,
                            const render_options&);
scheme_frame render_enc_xy(const scene&, const prepared_scene&, const std::vector<std::int32_t>&,
                           const render_options&);
scheme_frame render_enc_spheremap(const scene&, const prepared_scene&, const std::vector<std::int32_t>&,
                                  const render_options&);
scheme_frame render_enc_stereographic(const scene&, const prepared_scene&, const std::vector<std::int32_t>&,
                                      const render_options&);
scheme_frame render_enc_octahedral(const scene&, const prepared_scene&, const std::vector<std::int32_t>&,
                                   const render_options&);

// Seed 002's quality measure (normal_encoding/seed_psnr.hpp) on the scene: per covered pixel the
// interpolated view-space vector v (normal-map texel through the barycentrically interpolated vertex
// frame, then the camera's rotation; not unit) and n = normalize(v). Three ways to feed an encoder:
//   given:     n given, error against n — what the seed measures: the error of the encoding
//              against the normal it was given (for xyz "only because of quantization");
//   raw_self:  v given, error against v — the 2009 pipeline if n1 was the vector as interpolated;
//   bug_2009:  v given, error against n — the 2009 encoders' missing normalise as an error (the bug
//              the seed's header admits), kept apart from the seed's measure.
// And as the seed measured (normal_encoding/seed_2009.hpp): as_2009 gives the 2009 encoder g, the
// view-space vertex normals alone interpolated across the triangle (no normal map; the seed mentions
// none), and takes the error against g itself (as_2009.vs_given, the seed's reading) and against
// normalize(g) (as_2009.vs_unit).
// facing_away: pixels with n.z < 0 (view space looks down −z), where #1 decodes the wrong z sign.
struct psnr_row {
  std::string method;
  std::size_t pixels = 0, facing_away = 0;
  normal_encoding::seed_error given, given_8bit_image, raw_self, bug_2009;
  double mean_input_length = 0;  // of v
  normal_encoding::seed_2009_error as_2009;
};
std::vector<psnr_row> normal_encoding_psnr(const scene& s, const prepared_scene& ps,
                                           const std::vector<std::int32_t>& visible, int bits);

}  // namespace gsdot3::pipeline
