// proofs/paper_code.hpp — the paper's own C code (Appendices 1 and 2), transcribed statement by
// statement. These are the paper's ENCODERS: they produce the textures and palettes the GS is fed
// (inputs to the proofs), they are not part of the GS model.
//
// Transcription notes (kept as written, including the quirks):
// - Appendix 1 computes in float: `(x+0.5f)/((float) iWidth)`, float sqrt, and `(s-0.5)*m`, whose
//   0.5 is a double literal, so that product is formed in double and rounded to float.
//   nearest() is `(int)(x+0.5f)` mirrored for negatives (ties away from zero).
// - Appendix 2 truncates `(int)(nx * 127.9f)` toward zero, takes `(int) sqrt(int)` (double sqrt) and
//   its final clamp tests `iX > 255` where `alpha > 255` was surely meant; the transcription keeps
//   the test as printed and the proofs report what it does.
// This TU family is built with -ffp-contract=off so no multiply-add is fused.
#pragma once

#include <cstdint>
#include <vector>

namespace gsdot3::proofs::paper {

// Appendix 1: nearest(x).
int nearest(float x) noexcept;

// One texel of GenerateSphereMap: the packed (r, g, b) = 128 − nearest(127·L) and the float unit
// vector L it packed; `inside` is the `Lz >= -1` branch (outside it the texel is the zero vector
// (128, 128, 128)).
struct sphere_texel {
  int r = 128, g = 128, b = 128;
  bool inside = false;
  float lx = 0, ly = 0, lz = 0;
};
sphere_texel sphere_map_texel(int x, int y, int width, int height) noexcept;
// GenerateSphereMap's memory image: (b << 16) | (g << 8) | r per texel, row by row.
std::vector<std::uint32_t> generate_sphere_map(int width, int height);

// Appendix 2: the two-pass packing of a unit normal.
struct packed_normal {
  int iX = 0, iY = 0, iZ = 0;
  int R_pos = 0, G_pos = 0, B_pos = 0;
  int R_neg = 0, G_neg = 0, B_neg = 0;
  int delta = 0;
  int alpha = 0;            // after the printed clamp
  int alpha_unclamped = 0;  // (3*128 + delta + 1) / 3
  bool assert_le = true;    // assert((iX*iX + iY*iY + iZ*iZ) <= 128*128)
  bool assert_gt = true;    // assert((iX*iX + iY*iY + (iZ+1)*(iZ+1)) > 128*128)
};
packed_normal pack_normal(float nx, float ny) noexcept;
// The same code from the point where iX and iY are known (after `(int)(n * scale)`), for the
// enumeration of every (iX, iY) the first lines can produce.
packed_normal pack_normal_from(int iX, int iY) noexcept;

// Section 3.5: one component of the packed tolight vector, (char)(s·T) (truncation toward zero;
// |s·T| < 128 is required for the cast to be defined).
int pack_light_component(float s, float t) noexcept;

}  // namespace gsdot3::proofs::paper
