// proofs/claims_two_pass_text.hpp — what section 3.5's claims (claims_two_pass.cpp and
// claims_two_pass_interpolated.cpp) share: the paper's s, a light as text, the tolight domain note.
#pragma once

#include <string>

#include "proofs/domains.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs::claims::two_pass_text {

inline constexpr int paper_s = 122;
// "l = (x, y, z) colour 0xBBGGRR", the light as the vertex colour the pipeline packs.
std::string describe_light(const ivec3& l);
// The outcome, with a note under tolight = attenuated_T that the ball of lights gives the same.
outcome for_domain(outcome o, const sweep_config& cfg);

}  // namespace gsdot3::proofs::claims::two_pass_text
