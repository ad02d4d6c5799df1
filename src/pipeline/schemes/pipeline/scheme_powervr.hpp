// pipeline/scheme_powervr.hpp — seed 004 (PowerVR Series 2 polar bump mapping) as methods of the
// shared report (scheme_methods.cpp). See scheme_powervr.cpp for what each method does.
#pragma once

#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline::powervr_methods {

scheme_frame flat_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                        const render_options& o);
scheme_frame flat_fixed8(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                         const render_options& o);
scheme_frame gouraud_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                           const render_options& o);
scheme_frame pixel_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                         const render_options& o);
scheme_frame cheap_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                         const render_options& o);

}  // namespace gsdot3::pipeline::powervr_methods
