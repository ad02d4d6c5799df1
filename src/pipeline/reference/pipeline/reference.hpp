// pipeline/reference.hpp — the float reference (GLM, built with -ffp-contract=off): the same mesh,
// the same visible triangle per pixel and the same texel footprint as the GS render, with the dot
// product evaluated in float.
//   renormalised:     128 · fade · normalize(N) · normalize(Σ λ_i T_i)     (PC-style per-pixel DOT3)
//   not renormalised: 128 · normalize(N) · Σ λ_i (fade_i · T_i)            (what interpolation gives)
// λ are the exact barycentric weights of the pixel centre in the 12.4 triangle, fade = Σ λ_i fade_i,
// N the palette normal of the sampled texel (bilinear: the 4-bit-weight blend of the four texels'
// palette normals, as the GS weighs them). Their difference is the normalisation error; a method's
// difference from "not renormalised" is its fixed-point error.
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct reference_frame {
  int width = 0, height = 0;
  std::vector<std::vector<float>> renormalised, unnormalised;  // [light][pixel], 1/128 units; NaN = not covered
  std::vector<std::uint32_t> colour;  // lit frame from the renormalised dot products (A8B8G8R8)
};

// `visible_triangle` comes from the GS render's step 1 (the same per-pixel winner), `plain_triangle`
// from its step 5 (frame::plain_triangle; empty: none), whose pixels the lit frame shows composed by
// compose_plain. `power`: the lit frame uses (max(dot, 0)/128)^power per light (the ILP's exponent).
reference_frame render_reference(const scene& s, const prepared_scene& ps,
                                 const std::vector<std::int32_t>& visible_triangle, bool bilinear, double power = 1.0,
                                 const std::vector<std::int32_t>& plain_triangle = {});

}  // namespace gsdot3::pipeline
