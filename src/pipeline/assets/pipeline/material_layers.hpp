// pipeline/material_layers.hpp — the normal maps of a file's materials as the layers of the scene's
// normal map (scene.hpp, mesh_import.hpp's material_layers): which map each drawn mesh's material
// names, distinct maps a layer each, the materials without one a flat layer.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "pipeline/mesh_import.hpp"
#include "pipeline/mesh_repair.hpp"

struct aiScene;  // <assimp/scene.h>

namespace gsdot3::pipeline {

// The layers of the drawn meshes' materials and, per mesh of s, its layer (mesh_layer) and the UV set
// its map reads (uv_set). An external map must be in `dir` or below it (std::runtime_error otherwise).
material_layers layers_of(const aiScene& s, const std::vector<source_instance>& inst, const std::filesystem::path& dir,
                          std::vector<std::uint16_t>& mesh_layer, std::vector<unsigned>& uv_set);

}  // namespace gsdot3::pipeline
