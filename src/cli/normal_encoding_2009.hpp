// cli/normal_encoding_2009.hpp — gsdot3 normal-encoding's table of seed 002 as the 2009 article
// measured it (normal_encoding/seed_2009.hpp): the interpolated vertex normals not normalised, the
// 2009 encoders, the error against the vector given; on the scene and on faceted spheres.
#pragma once

#include <vector>

#include "pipeline/scheme_normal_encoding.hpp"

namespace gsdot3::cli {

// seed_2009_db[i]: the seed's published figure for rows[i] (0: none).
void print_as_measured_2009(const std::vector<pipeline::psnr_row>& rows, const std::vector<double>& seed_2009_db,
                            int bits);

}  // namespace gsdot3::cli
