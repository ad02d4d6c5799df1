// pipeline/material_layers.cpp — see material_layers.hpp.
#include "pipeline/material_layers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include "pipeline/asset_folder.hpp"

namespace gsdot3::pipeline {

namespace {

// Material k's normal map: glTF normalTexture / MTL norm (aiTextureType_NORMALS), else an MTL bump /
// map_Bump (aiTextureType_HEIGHT), with its scale and UV set; nullopt: none.
std::optional<texture_ref> normal_map_of(const aiScene& s, unsigned k, const std::filesystem::path& dir) {
  if (k >= s.mNumMaterials || s.mMaterials[k] == nullptr) return std::nullopt;
  const aiMaterial& mat = *s.mMaterials[k];
  for (aiTextureType type : {aiTextureType_NORMALS, aiTextureType_HEIGHT}) {
    aiString path;
    unsigned uv_set = 0;
    if (mat.GetTexture(type, 0, &path, nullptr, &uv_set) != aiReturn_SUCCESS || path.length == 0) continue;
    texture_ref t;
    t.name = path.C_Str();
    t.slot = type == aiTextureType_NORMALS ? "normal" : "bump";
    t.uv_set = uv_set;
    ai_real scale = 1;
    if (mat.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(type, 0), scale) == aiReturn_SUCCESS && std::isfinite(scale))
      t.scale = static_cast<float>(scale);
    if (const aiTexture* tex = s.GetEmbeddedTexture(path.C_Str())) {
      if (tex->mHeight == 0) {  // compressed: mWidth bytes of an image file
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(tex->pcData);
        t.embedded.assign(bytes, bytes + tex->mWidth);
      } else {  // raw BGRA texels
        t.raw = {static_cast<int>(tex->mWidth), static_cast<int>(tex->mHeight), 3, {}};
        for (std::size_t i = 0; i < static_cast<std::size_t>(tex->mWidth) * tex->mHeight; ++i)
          t.raw.data.insert(t.raw.data.end(), {tex->pcData[i].r, tex->pcData[i].g, tex->pcData[i].b});
      }
    } else {
      std::string name = t.name;
      std::replace(name.begin(), name.end(), '\\', '/');  // Windows exporters
      if (const std::string why = outside_folder(dir, (dir / name).string()); !why.empty())
        throw std::runtime_error("the material's normal map " + name + " is " + why +
                                 "; only files in the mesh's folder or below it are read");
      t.file = dir / std::filesystem::path(name);
    }
    return t;
  }
  return std::nullopt;
}

std::string material_name(const aiScene& s, unsigned k) {
  aiString n;
  if (k < s.mNumMaterials && s.mMaterials[k] != nullptr &&
      s.mMaterials[k]->Get(AI_MATKEY_NAME, n) == aiReturn_SUCCESS && n.length > 0)
    return n.C_Str();
  return "material " + std::to_string(k);
}

}  // namespace

material_layers layers_of(const aiScene& s, const std::vector<source_instance>& inst, const std::filesystem::path& dir,
                          std::vector<std::uint16_t>& mesh_layer, std::vector<unsigned>& uv_set) {
  material_layers out;
  mesh_layer.assign(s.mNumMeshes, 0);
  uv_set.assign(s.mNumMeshes, 0);
  std::map<unsigned, int> of_material;  // −1: no map, else its layer
  std::vector<unsigned> flat_meshes;
  for (const source_instance& in : inst) {
    if (s.mMeshes[in.mesh] == nullptr) continue;            // skipped by the conversion too (fuzz/mesh_from_scene)
    const unsigned k = s.mMeshes[in.mesh]->mMaterialIndex;  // out of range or null: no map
    const auto [at_k, fresh] = of_material.try_emplace(k, -1);
    int& layer = at_k->second;
    if (fresh) {
      if (std::optional<texture_ref> t = normal_map_of(s, k, dir)) {
        auto same = [&](const texture_ref& u) {
          return u.name == t->name && u.slot == t->slot && u.scale == t->scale && u.uv_set == t->uv_set;
        };
        auto at = std::find_if(out.maps.begin(), out.maps.end(), same);
        if (at == out.maps.end()) at = out.maps.insert(at, std::move(*t));
        at->materials.push_back(material_name(s, k));
        layer = static_cast<int>(at - out.maps.begin());
      } else {
        out.flat_materials.push_back(material_name(s, k));
      }
    }
    if (layer >= 0) {
      mesh_layer[in.mesh] = static_cast<std::uint16_t>(layer);
      uv_set[in.mesh] = out.maps[static_cast<std::size_t>(layer)].uv_set;
    } else {
      flat_meshes.push_back(static_cast<unsigned>(in.mesh));
    }
  }
  if (out.maps.empty()) out.flat_materials.clear();  // no maps: the scene's one map on every triangle
  if (out.count() > max_layers)
    throw std::runtime_error("the materials name " + std::to_string(out.maps.size()) + " normal maps, " +
                             std::to_string(out.count()) + " layers with the flat one; at most " +
                             std::to_string(max_layers) + " layers are drawn");
  for (unsigned m : flat_meshes) mesh_layer[m] = static_cast<std::uint16_t>(out.maps.size());  // 0 without maps
  return out;
}

}  // namespace gsdot3::pipeline
