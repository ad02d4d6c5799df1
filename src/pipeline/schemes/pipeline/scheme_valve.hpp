// pipeline/scheme_valve.hpp — seed 001's report methods (rows of scheme_methods.cpp).
#pragma once

#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {

scheme_frame render_valve_rnm(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                              const render_options& o);
scheme_frame render_valve_ssbump(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                                 const render_options& o);

}  // namespace gsdot3::pipeline
