// proofs/domains.hpp — the finite input sets the claims enumerate, each derived exactly.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "proofs/paper_code.hpp"

namespace gsdot3::proofs {

using ivec3 = std::array<int, 3>;

// Every (iX, iY) that Appendix 2's `(int)(n * 127.9f)` produces from a unit normal, packed.
//
// Argument: iX = trunc(fl(nx·127.9f)). For iX != 0 this needs |nx|·127.9f >= |iX| up to one float
// rounding (relative 2^-24), and iX = 0 needs nothing. So a pair is reachable iff some point of the
// unit disc has |nx| >= |iX|/127.9f and |ny| >= |iY|/127.9f, i.e. iX² + iY² <= 127.9f² = 16358.41:
// iX² + iY² <= 16358. The integer margin (0.41 below, 0.59 above) is 10^3 times the float rounding,
// so float arithmetic changes nothing; appendix2_normals() also checks each pair constructively by
// finding a float nx, ny that the paper's code maps to it, with nx² + ny² <= 1.
const std::vector<paper::packed_normal>& appendix2_normals();  // computed once

// Every packed tolight vector (char)(s·T) of a real unit T (section 3.5), 1 <= s <= 127.
//
// Argument: the cast truncates toward zero, so component k comes from s·T_i in [k, k+1) for k > 0,
// (k−1, k] for k < 0 and (−1, 1) for k = 0. The unit sphere (radius s after scaling) meets that
// half-open box iff its nearest point is inside the sphere and its far corner outside:
// Σ k_i² <= s² < Σ (|k_i| + 1)².
std::vector<ivec3> packed_lights(int s);
bool is_packed_light(int s, const ivec3& l) noexcept;  // the membership test above
// The domain option tolight = attenuated_T: (char)(s·T) for |T| <= 1 is every cell whose nearest
// point is in the ball, Σ k_i² <= s² (the shell above and its inside).
std::vector<ivec3> attenuated_lights(int s);

// Every 8-bit normal-map vector b = round(127·n) of a unit n with n_z >= 0 (section 3.6; stored
// centred at 128). The cell [b − ½, b + ½] meets the sphere of radius 127 iff
// Σ max(2|b_i| − 1, 0)² <= 4·127² <= Σ (2|b_i| + 1)² (ties are measure-zero and taken as reachable).
// full_sphere: any unit n (z from −127), the domain option normal_map=full_sphere.
std::vector<ivec3> normal_map_vectors(bool full_sphere = false);

// Appendix 1's sphere map of size × size: each texel's signed vector a = 128 − (r, g, b) (the zero
// vector outside the disc), in texel order.
std::vector<ivec3> sphere_map_vectors(int size);

}  // namespace gsdot3::proofs
