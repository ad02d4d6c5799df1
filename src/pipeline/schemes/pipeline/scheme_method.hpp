// pipeline/scheme_method.hpp — the other seeds' normal-mapping schemes (src/schemes/*) as methods of
// the shared report: each renders the same scene on the same geometry as the GS methods (the GS
// render's visible triangle per pixel, walked by pixel_walk.hpp) and gives, per light and covered
// pixel, its value of the dot product in the report's unit, so the same error tables compare it with
// the same float reference.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "pipeline/prepare.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct scheme_frame {
  // [light][pixel]: the scheme's 128·fade·N·L (1/128 units, as the reference's "renormalised"
  // value), NaN where no triangle is visible.
  std::vector<std::vector<float>> dot;
  std::vector<std::uint32_t> colour;  // the lit frame (A8B8G8R8), e.g. from compose_lit
};

struct scheme_method {
  std::string_view name;     // report and --method name, unique, e.g. "rnm"
  std::string_view seed;     // which seed it comes from, e.g. "001 (Green 2007)"
  std::string_view summary;  // one sentence: what is stored per texel and how it is evaluated
  // The scheme cannot represent N·L < 0 (its output is clamped at 0): its errors are measured
  // against max(reference, 0).
  bool non_negative = false;
  scheme_frame (*render)(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible_triangle,
                         const render_options& o) = nullptr;
};

// The table of scheme methods (scheme_methods.cpp), in seed order; the CLI's --method names.
const std::vector<scheme_method>& scheme_methods();
const scheme_method* find_scheme_method(std::string_view name) noexcept;

}  // namespace gsdot3::pipeline
