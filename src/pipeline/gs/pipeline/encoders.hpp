// pipeline/encoders.hpp — the paper's table and palette builders (VU1/tool-side, float, value level):
// Appendix 1 (sphere map), Appendix 2 (two-pass normal packing), the four-pass reordered palettes
// (figure 3), Breugelmans' positive/negative palettes (section 2) and the intensity look-up palette
// (section 3.3). These produce the GS's inputs; the GS arithmetic that consumes them is in gs_arith.
// Appendix 1, Appendix 2 and the (char)(s·T) packing are src/proofs' transcriptions of the paper's
// code (proofs/paper_code.hpp), used here, not copied.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "gs_arith/clut.hpp"
#include "gs_arith/colour.hpp"

namespace gsdot3::pipeline {

// Appendix 1's nearest() (proofs::paper::nearest): round half away from zero.
int nearest(float x);

// Appendix 2 (proofs::paper::pack_normal): (R_pos, G_pos, B_pos, 0x80) and (R_neg, G_neg, B_neg, n'_a)
// for a unit tangent-space normal.
struct two_pass_texel {
  gs::rgba8 positive, negative;
};
two_pass_texel pack_two_pass(glm::vec3 n);

// The packed tolight vector of section 3.5: 128 + (char)(s·T) per component, alpha 0x80.
gs::rgba8 pack_tolight(glm::vec3 t, int s);

// Appendix 1 (proofs::paper::generate_sphere_map): the 24-bit sphere map as A8B8G8R8 words (alpha 0).
std::vector<std::uint32_t> sphere_map(int width, int height);
// Section 3.6's spot-light texture, spot_map_size² A8B8G8R8 words: RGB 0x80 (the blend's Cs = 128) and
// alpha nearest(128·spot_intensity) at each texel's centre (the blend's As, 128 = 1.0).
std::vector<std::uint32_t> spot_map();

// Sphere-map texture coordinates (s, t) in 0..1 of a unit vector (section 3.6).
struct st {
  float s, t;
};
st sphere_coordinates(glm::vec3 t);

// Figure 3(b): for axis 0/1/2 (X/Y/Z), entries (128, 128, 128, 128 + nearest(127·n_axis)).
gs::clut_buffer reordered_palette(const std::vector<glm::vec3>& normals, int axis);

// Section 3.6's "three 8 bit normal maps" instead of the reordered palettes: axis `axis`'s map holds
// per texel 128 + nearest(127·n_axis), the byte figure 3(b) puts in alpha, and every axis pass reads
// its map through one ramp palette (128, 128, 128, i), so entry i carries the byte i into alpha.
std::vector<std::uint8_t> component_map(const std::vector<glm::vec3>& normals, int axis);
gs::clut_buffer component_ramp_palette();

// Section 2 (Breugelmans 2002): entries nearest(127·max(±n, 0)) per component, alpha 0x80.
gs::clut_buffer signed_side_palette(const std::vector<glm::vec3>& normals, bool negative);
// Two-pass palettes from Appendix 2.
gs::clut_buffer two_pass_palette(const std::vector<glm::vec3>& normals, bool negative);
// Section 3.5's three-pass terms: (128 + Max(−n, 0) − Max(n, 0)) per component of Appendix 2's packed
// normal (its R_neg − R_pos, ...), alpha 0x80; each is in 1..255 since −127 <= iX, iY <= 127 and
// 0 <= iZ <= 128 (appendix2.packing).
gs::clut_buffer three_pass_terms_palette(const std::vector<glm::vec3>& normals);

// Section 3.3: the ILP holds 1, 2, ..., 128 in the first 128 entries (dot products 0..127) and 0 in
// the last 128 (negative dot products); the R+G+B sum arrives offset by 128, so entry v holds
// ILP[(v − 128) mod 256]. `power` > 1 raises the intensities for specular (section 3.7).
gs::clut_buffer intensity_palette(double power = 1.0);

// A grey identity palette (i, i, i, 0x80): what a channel read through PSMT8/PSMT8H passes on.
gs::clut_buffer identity_palette();

}  // namespace gsdot3::pipeline
