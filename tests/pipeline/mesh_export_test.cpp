// --export-mesh (pipeline/mesh_export.hpp): the .glb read back by an independent reader (tinygltf's
// loader) carries TANGENT.w as glTF 2.0 defines it (bitangent = w · NORMAL × TANGENT points up the
// image), and re-imported through assimp it gives the same vertices and frames.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include <glm/geometric.hpp>
#include <tiny_gltf.h>

#include "common/temp_dir.hpp"
#include "pipeline/mesh_export.hpp"
#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;
const fs::path data = fs::path(GSDOT3_TEST_DATA) / "meshes";

std::vector<float> floats_of(const tinygltf::Model& g, int accessor) {
  const tinygltf::Accessor& a = g.accessors[static_cast<std::size_t>(accessor)];
  const tinygltf::BufferView& v = g.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::size_t n =
      a.count * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)));
  std::vector<float> out(n);
  std::memcpy(out.data(), g.buffers[static_cast<std::size_t>(v.buffer)].data.data() + v.byteOffset + a.byteOffset,
              n * sizeof(float));
  return out;
}

// mirrored_strip.obj: left quad u along +x, right quad u along −x, OBJ's v up the image (+y). The
// bitangent points up the image, +y, on both: left t = +x, n × t = +y, w = +1; right t = −x,
// n × t = −y, w = −1.
TEST(MeshExport, TangentWIsGltfsHandedness) {
  const fs::path d = gsdot3::test::fresh_temp_dir("gsdot3-mesh-export-w");
  const imported_mesh im = import_mesh(data / "mirrored_strip.obj");
  export_mesh_glb(im.model, d / "strip.glb");
  tinygltf::Model g;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&g, &err, &warn, (d / "strip.glb").string())) << err;
  ASSERT_EQ(g.meshes.size(), 1u);
  const tinygltf::Primitive& p = g.meshes[0].primitives.at(0);
  for (const char* name : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"})
    ASSERT_EQ(p.attributes.count(name), 1u) << name;
  const std::vector<float> pos = floats_of(g, p.attributes.at("POSITION")),
                           tan = floats_of(g, p.attributes.at("TANGENT"));
  ASSERT_EQ(tan.size(), pos.size() / 3 * 4);
  std::size_t left = 0, right = 0;
  for (std::size_t i = 0; i < pos.size() / 3; ++i) {
    const float x = pos[3 * i];
    if (x == 1.0f) continue;  // the middle column belongs to both quads
    const bool is_right = x > 1.0f;
    EXPECT_EQ(tan[4 * i], is_right ? -1.0f : 1.0f) << "vertex " << i;
    EXPECT_EQ(tan[4 * i + 3], is_right ? -1.0f : 1.0f) << "vertex " << i;
    ++(is_right ? right : left);
  }
  EXPECT_EQ(left, 2u);
  EXPECT_EQ(right, 2u);
  fs::remove_all(d);
}

// Export, then import the .glb: the same triangles, corner by corner, positions, normals, tangents,
// bitangents and UVs within float rounding (the file's TANGENTs are used: "file (TANGENT)").
TEST(MeshExport, ReimportGivesTheSameVerticesAndFrames) {
  const fs::path d = gsdot3::test::fresh_temp_dir("gsdot3-mesh-export-round-trip");
  for (const char* file : {"mikk_mirrored.glb", "cube_seams.obj", "mirrored_strip.obj"}) {
    const imported_mesh a = import_mesh(data / file);
    export_mesh_glb(a.model, d / "out.glb");
    const imported_mesh b = import_mesh(d / "out.glb");
    EXPECT_EQ(b.report.tangents, "file (TANGENT)") << file;
    ASSERT_EQ(a.model.triangles.size(), b.model.triangles.size()) << file;
    for (std::size_t t = 0; t < a.model.triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k) {
        const vertex& u = a.model.vertices[a.model.triangles[t][k]];
        const vertex& v = b.model.vertices[b.model.triangles[t][k]];
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(u.position[i], v.position[i], 1e-6f) << file << " triangle " << t;
          EXPECT_NEAR(u.normal[i], v.normal[i], 1e-6f) << file << " triangle " << t;
          EXPECT_NEAR(u.tangent[i], v.tangent[i], 1e-6f) << file << " triangle " << t;
          EXPECT_NEAR(u.bitangent[i], v.bitangent[i], 1e-6f) << file << " triangle " << t;
        }
        EXPECT_NEAR(u.uv.x, v.uv.x, 1e-6f) << file << " triangle " << t;
        EXPECT_NEAR(u.uv.y, v.uv.y, 1e-6f) << file << " triangle " << t;
      }
  }
  fs::remove_all(d);
}

}  // namespace
}  // namespace gsdot3::pipeline
