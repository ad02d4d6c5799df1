// pipeline/mesh_export.hpp — the renderer's mesh as a binary glTF 2.0 file (.glb), so a user can
// open the tangent frames the renderer used in Blender or any glTF viewer.
#pragma once

#include <filesystem>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// One mesh, one node: POSITION, NORMAL, TANGENT and TEXCOORD_0 per vertex and the triangles.
// TANGENT.w is glTF's handedness: bitangent = w · NORMAL × TANGENT points up the image (glTF 2.0
// "Meshes"), the opposite of the renderer's bitangent (v runs down), so w = −(renderer sign).
// TEXCOORD_0 is the renderer's UV unchanged (glTF's v runs down the image as the renderer's does).
// Written through tinygltf (Debian libtinygltf-dev): assimp 5.2's glTF2 exporter writes no TANGENT
// (glTF2Exporter::ExportMeshes fills POSITION, NORMAL, TEXCOORD and COLOR only). The file is
// written to a temporary name and renamed. Throws std::runtime_error "FILE: why".
void export_mesh_glb(const mesh& m, const std::filesystem::path& file);

}  // namespace gsdot3::pipeline
