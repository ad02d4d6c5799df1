// pipeline/raster.hpp — the pipeline's names for the GS rasteriser, which lives below it in
// gs_arith/rasteriser.hpp (the packet interpreter draws through the same unit).
#pragma once

#include "gs_arith/rasteriser.hpp"

namespace gsdot3::pipeline {

using gs::ceil_124;
using gs::covers;
using gs::make_plane;
using gs::plane;
using gs::rasterise_sprite;
using gs::rasterise_triangle;
using gs::scissor;
using gs::setup_triangle;
using gs::triangle_setup;
using gs::xy124;

}  // namespace gsdot3::pipeline
