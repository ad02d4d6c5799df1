// fuzz/mesh_from_scene.cpp — libFuzzer harness: gsdot3's conversion of an assimp scene
// (pipeline::from_scene: node instancing, conversion, normal/UV/tangent repairs, MikkTSpace, merging,
// the materials' normal-map layers) on scenes this harness builds from the bytes itself, in this process.
// No assimp parser runs: the imports run their parser and this conversion in a child process
// (child_process.hpp), where parse_inputs sees no coverage of it.
// The scene is well formed as assimp's importers leave one (counts match arrays, nodes form a tree)
// but its content is anything: positions, normals, UVs, tangents NaN / infinite / huge / on a small
// grid (so triangles collapse and positions repeat), face indices out of range, points, lines,
// polygons, meshes without positions, normals, UVs or tangents, null meshes and materials, node
// references out of range, mirroring / collapsing / arbitrary node transforms, up to 64 meshes and
// 34 nodes, normal-map names embedded ("*N", raw or compressed) or external.
// Bad content must come back as std::runtime_error "<fuzz>: why"; an accepted mesh must hold the
// postconditions of mesh_check.hpp and report what the scene holds (counted here from the scene).
//
// Input layout: every value is one byte (or four for a float's bit pattern) taken with
// FuzzedDataProvider::ConsumeIntegral, which reads from the END of the input; a seed is written as
// the byte sequence below, reversed (mesh_from_scene_seeds.py writes corpus/mesh_from_scene/).
//   options  (bit 0 flat normals, bits 1-2 uv projection (0 automatic), bit 3 MikkTSpace always,
//            bit 4 no root, bits 5-7 the crease angle: 0 the default, k 30·(k − 1)°)
//   meshes   count % 65, each: attributes (0xff: null; bit 0 no positions, 1 normals, 2 UVs,
//            3 UVs in channel 1 only, 4 tangents, 5 bitangents), vertices % 65, the present
//            attributes' floats (all positions, then all normals, UVs (two each), tangents,
//            bitangents), faces % 65, each: size code (face_sizes), indices (0xff: out of range,
//            then a byte added to the vertex count), material index % 6
//   materials count % 5, each: kind (0xff: null; bit 0 normal texture, bit 1 height texture), name code
//   textures count % 3, each: kind (bit 0 raw texels), name code, then length % 64 and the bytes
//            (compressed), or width and height % 4 + 1 and 4 bytes a texel (raw)
//   nodes    extra nodes % 34; the root, then each extra node: (parent index, for extra nodes),
//            transform code and its operands, mesh references % 5, each as a face index is
//   describe bit 0: import_options::describe_empty (mesh-info's: nothing to draw described, not refused)
//   transform code % 8: 2 mirror (axis byte), 3 mirror all, 4 scale (3 floats), 5 translate (3 floats),
//            6 rotate by k·90° (k byte, axis byte), 7 sixteen floats (row by row), else identity
//   float    code < 8 NaN, < 16 ±infinity, < 24 the next four bytes' bit pattern, < 32 an extreme
//            value (huge, denormal, −0, FLT_MAX, …), else on the grid (code − 32) % 17 / 4 − 2
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <set>
#include <string>
#include <vector>

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>
#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_check.hpp"
#include "mesh_check.hpp"
#include "pipeline/mesh_import.hpp"

namespace {

using gsdot3::fuzz::require;
namespace pl = gsdot3::pipeline;

constexpr const char* scene_name = "<fuzz>";
constexpr const char* texture_names[] = {"*0", "*1", "*9", "normal.png", "maps\\normal.png", "", "../n.tga", "*-1"};

struct scene_reader {
  FuzzedDataProvider& in;

  unsigned byte() { return in.ConsumeIntegral<std::uint8_t>(); }

  float value() {
    const unsigned c = byte();
    if (c < 8) return std::numeric_limits<float>::quiet_NaN();
    if (c < 16) return (c & 1) != 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    if (c < 24) return std::bit_cast<float>(in.ConsumeIntegral<std::uint32_t>());
    constexpr std::array<float, 8> extreme = {1e30f, -1e30f, 1e-40f, -0.0f, std::numeric_limits<float>::max(),
                                              1e-7f, 1e7f,   -3e-39f};
    if (c < 32) return extreme[c - 24];
    return static_cast<float>((c - 32) % 17) / 4.0f - 2.0f;
  }

  aiVector3D vec3() {
    const float x = value(), y = value(), z = value();
    return {x, y, z};
  }

  // A vertex (or mesh) index below `count`, or now and then one at or beyond it.
  unsigned index(unsigned count) {
    const unsigned c = byte();
    return c == 0xff ? count + byte() : c % std::max(count, 1u);
  }

  aiMatrix4x4 transform() {
    aiMatrix4x4 m;  // identity
    switch (byte() % 8) {
      case 2: {  // mirrored in one axis
        aiVector3D s(1.0f, 1.0f, 1.0f);
        s[byte() % 3] = -1.0f;
        aiMatrix4x4::Scaling(s, m);
        break;
      }
      case 3: aiMatrix4x4::Scaling(aiVector3D(-1.0f, -1.0f, -1.0f), m); break;  // mirrored in all three
      case 4: aiMatrix4x4::Scaling(vec3(), m); break;                           // any scale, zero included
      case 5: aiMatrix4x4::Translation(vec3(), m); break;
      case 6: {
        const float angle = static_cast<float>(byte() % 4) * 1.5707964f;
        switch (byte() % 3) {
          case 0: aiMatrix4x4::RotationX(angle, m); break;
          case 1: aiMatrix4x4::RotationY(angle, m); break;
          default: aiMatrix4x4::RotationZ(angle, m); break;
        }
        break;
      }
      case 7:
        for (unsigned r = 0; r < 4; ++r)
          for (unsigned c = 0; c < 4; ++c) m[r][c] = value();
        break;
      default: break;
    }
    return m;
  }
};

constexpr std::array<unsigned, 8> face_sizes = {3, 3, 3, 4, 1, 2, 0, 6};

// What the conversion must report for an accepted scene, counted from the scene as built.
struct expected {
  std::size_t instances = 0, meshes = 0, points = 0, lines = 0;
  // The distinct maps (name, slot: "normal" before "bump") the instanced meshes' materials name, and
  // whether one of those meshes has a material without a map (the flat layer when there are maps).
  std::set<std::pair<std::string, std::string>> maps;
  bool unmapped = false;
};

aiMesh* read_mesh(scene_reader& r) {
  const unsigned attributes = r.byte();
  if (attributes == 0xff) return nullptr;
  auto m = std::make_unique<aiMesh>();
  const unsigned n = r.byte() % 65;
  m->mNumVertices = n;
  auto attribute = [&](bool present, unsigned components) {
    if (!present) return static_cast<aiVector3D*>(nullptr);
    auto* a = new aiVector3D[n];
    for (unsigned i = 0; i < n; ++i)
      for (unsigned k = 0; k < components; ++k) a[i][k] = r.value();
    return a;
  };
  m->mVertices = attribute((attributes & 1) == 0, 3);
  m->mNormals = attribute((attributes & 2) != 0, 3);
  const unsigned uv_channel = (attributes & 8) != 0 ? 1 : 0;
  m->mTextureCoords[uv_channel] = attribute((attributes & 4) != 0, 2);
  m->mNumUVComponents[uv_channel] = 2;
  m->mTangents = attribute((attributes & 16) != 0, 3);
  m->mBitangents = attribute((attributes & 32) != 0, 3);
  m->mNumFaces = r.byte() % 65;
  m->mFaces = new aiFace[m->mNumFaces];
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    aiFace& face = m->mFaces[f];
    face.mNumIndices = face_sizes[r.byte() % face_sizes.size()];
    face.mIndices = new unsigned[face.mNumIndices];
    for (unsigned k = 0; k < face.mNumIndices; ++k) face.mIndices[k] = r.index(n);
  }
  m->mMaterialIndex = r.byte() % 6;
  return m.release();
}

aiMaterial* read_material(scene_reader& r) {
  const unsigned kind = r.byte();
  const aiString name(texture_names[r.byte() % std::size(texture_names)]);
  if (kind == 0xff) return nullptr;
  auto m = std::make_unique<aiMaterial>();
  if ((kind & 1) != 0) m->AddProperty(&name, AI_MATKEY_TEXTURE(aiTextureType_NORMALS, 0));
  if ((kind & 2) != 0) m->AddProperty(&name, AI_MATKEY_TEXTURE(aiTextureType_HEIGHT, 0));
  return m.release();
}

aiTexture* read_texture(scene_reader& r) {
  auto t = std::make_unique<aiTexture>();
  const bool raw = (r.byte() & 1) != 0;
  t->mFilename = aiString(texture_names[r.byte() % std::size(texture_names)]);
  if (raw) {
    t->mWidth = r.byte() % 4 + 1;
    t->mHeight = r.byte() % 4 + 1;
    t->pcData = new aiTexel[t->mWidth * t->mHeight];
    for (unsigned i = 0; i < t->mWidth * t->mHeight; ++i)
      t->pcData[i] = {static_cast<unsigned char>(r.byte()), static_cast<unsigned char>(r.byte()),
                      static_cast<unsigned char>(r.byte()), static_cast<unsigned char>(r.byte())};
  } else {  // compressed: mWidth bytes of an image file
    t->mWidth = r.byte() % 64;
    t->mHeight = 0;
    t->pcData = new aiTexel[(t->mWidth + 3) / 4 + 1];
    auto* bytes = reinterpret_cast<unsigned char*>(t->pcData);
    for (unsigned i = 0; i < t->mWidth; ++i) bytes[i] = static_cast<unsigned char>(r.byte());
  }
  return t.release();
}

std::string texture_of(const aiMaterial& m, aiTextureType type) {
  aiString path;
  return m.GetTexture(type, 0, &path) == aiReturn_SUCCESS ? std::string(path.C_Str()) : std::string();
}

// The node tree: the root, then extra nodes each hung below an earlier one. Counts the instances.
aiNode* read_nodes(scene_reader& r, const aiScene& s, expected& e, std::vector<char>& instanced) {
  const unsigned extra = r.byte() % 34;
  std::vector<aiNode*> nodes;
  std::vector<std::vector<aiNode*>> children;
  for (unsigned i = 0; i <= extra; ++i) {
    const unsigned parent = i == 0 ? 0 : r.byte() % i;
    auto* node = new aiNode("node " + std::to_string(i));
    node->mParent = i == 0 ? nullptr : nodes[parent];
    node->mTransformation = r.transform();
    node->mNumMeshes = r.byte() % 5;
    node->mMeshes = new unsigned[node->mNumMeshes];
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      node->mMeshes[k] = r.index(s.mNumMeshes);
      if (node->mMeshes[k] < s.mNumMeshes) {
        ++e.instances;
        instanced[node->mMeshes[k]] = 1;
      }
    }
    if (i > 0) children[parent].push_back(node);
    nodes.push_back(node);
    children.emplace_back();
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    nodes[i]->mNumChildren = static_cast<unsigned>(children[i].size());
    nodes[i]->mChildren = new aiNode*[children[i].size()];
    std::copy(children[i].begin(), children[i].end(), nodes[i]->mChildren);
  }
  return nodes[0];
}

void count_instanced(const aiScene& s, const std::vector<char>& instanced, expected& e) {
  for (unsigned i = 0; i < s.mNumMeshes; ++i) {
    const aiMesh* m = s.mMeshes[i];
    if (!instanced[i] || m == nullptr) continue;
    ++e.meshes;
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      e.points += m->mFaces[f].mNumIndices == 1;
      e.lines += m->mFaces[f].mNumIndices == 2;
    }
    const aiMaterial* mat = m->mMaterialIndex < s.mNumMaterials ? s.mMaterials[m->mMaterialIndex] : nullptr;
    const std::string normal = mat != nullptr ? texture_of(*mat, aiTextureType_NORMALS) : "";
    const std::string bump = mat != nullptr ? texture_of(*mat, aiTextureType_HEIGHT) : "";
    if (!normal.empty())
      e.maps.insert({normal, "normal"});
    else if (!bump.empty())
      e.maps.insert({bump, "bump"});
    else
      e.unmapped = true;
  }
}

template <typename T, typename Read>
void read_array(scene_reader& r, unsigned count, T**& array, unsigned& size, Read read) {
  size = count;
  array = new T*[count];
  for (unsigned i = 0; i < count; ++i) array[i] = read(r);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  scene_reader r{in};
  const unsigned flags = r.byte();
  pl::import_options options;
  options.normals = (flags & 1) != 0 ? pl::normals_mode::flat : pl::normals_mode::smooth;
  options.uvs = static_cast<pl::uv_projection>((flags >> 1) & 3);
  if ((flags >> 5) != 0) options.crease_degrees = static_cast<float>(30u * ((flags >> 5) - 1));
  options.tangents = (flags & 8) != 0 ? pl::tangent_mode::mikktspace : pl::tangent_mode::automatic;

  const auto scene = std::make_unique<aiScene>();
  read_array(r, r.byte() % 65, scene->mMeshes, scene->mNumMeshes, read_mesh);
  read_array(r, r.byte() % 5, scene->mMaterials, scene->mNumMaterials, read_material);
  read_array(r, r.byte() % 3, scene->mTextures, scene->mNumTextures, read_texture);
  expected e;
  std::vector<char> instanced(scene->mNumMeshes, 0);
  aiNode* root = read_nodes(r, *scene, e, instanced);
  if ((flags & 16) != 0) {
    delete root;
    e.instances = 0;
    std::fill(instanced.begin(), instanced.end(), 0);
  } else {
    scene->mRootNode = root;
  }
  count_instanced(*scene, instanced, e);

  options.describe_empty = (r.byte() & 1) != 0;  // mesh-info's: no triangle to draw is an empty mesh, not an error

  pl::imported_mesh m;
  try {
    m = pl::from_scene(*scene, scene_name, {}, "fuzz", options);
  } catch (const std::runtime_error& error) {
    const std::string what = error.what(), prefix = std::string(scene_name) + ": ";
    require(what.compare(0, prefix.size(), prefix) == 0 && what.find('\n') == std::string::npos,
            [&] { return "from_scene's error is not one line naming the scene: " + what; });
    return 0;
  }
  if (options.describe_empty && m.model.triangles.empty()) {  // described: the reason among its notices
    require(std::any_of(m.report.notices.begin(), m.report.notices.end(),
                        [](const std::string& n) { return n.find("nothing to draw") != std::string::npos; }),
            [] { return std::string("from_scene described an empty mesh without saying why"); });
    return 0;
  }
  gsdot3::fuzz::check_mesh(m.model);
  const pl::import_report& rep = m.report;
  require(rep.instances == e.instances && rep.meshes == e.meshes && rep.dropped_points == e.points &&
              rep.dropped_lines == e.lines && rep.triangles == m.model.triangles.size(),
          [&] {
            return "from_scene reports " + std::to_string(rep.instances) + " instances, " + std::to_string(rep.meshes) +
                   " meshes, " + std::to_string(rep.dropped_points) + " points, " + std::to_string(rep.dropped_lines) +
                   " lines, " + std::to_string(rep.triangles) + " triangles; the scene has " +
                   std::to_string(e.instances) + ", " + std::to_string(e.meshes) + ", " + std::to_string(e.points) +
                   ", " + std::to_string(e.lines) + ", " + std::to_string(m.model.triangles.size());
          });
  std::set<std::pair<std::string, std::string>> maps;
  for (const pl::texture_ref& t : m.layers.maps) maps.insert({t.name, t.slot});
  require(maps == e.maps && maps.size() == m.layers.maps.size() &&
              m.layers.flat_materials.empty() == (e.maps.empty() || !e.unmapped),
          [&] { return std::string("from_scene's normal-map layers do not match the instanced meshes' materials"); });
  require(m.layers.count() > 1 || m.model.layer.empty(), [&] {
    return "from_scene gave " + std::to_string(m.model.layer.size()) + " layer numbers for " +
           std::to_string(m.layers.count()) + " layers";
  });
  for (std::uint16_t k : m.model.layer)
    require(k < m.layers.count(), [&] { return "a triangle samples layer " + std::to_string(k) + " of none"; });
  return 0;
}
