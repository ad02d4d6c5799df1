// Mesh import (assimp + gsdot3's repairs) on small files shaped like what exporters write
// (tests/data/meshes, see its README): triangle counts, repairs counted, normal maps found, and
// one-line errors for bad files. Expected values follow from how each file was constructed.
#include <gtest/gtest.h>

#include "expect_error.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <glm/geometric.hpp>

#include "pipeline/mesh_import.hpp"
#include "common/temp_dir.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;
const fs::path data = fs::path(GSDOT3_TEST_DATA) / "meshes";

using test::expect_error;

void expect_near(glm::vec3 a, glm::vec3 b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// Every vertex has a unit normal, a unit tangent orthogonal to it and a unit bitangent ±(n × t).
void expect_frames(const mesh& m) {
  for (const vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, v.tangent), 0.0f, 1e-5f);
    EXPECT_NEAR(std::fabs(glm::dot(v.bitangent, glm::cross(v.normal, v.tangent))), 1.0f, 1e-5f);
  }
}

TEST(MeshImport, ObjWithoutUvsNamesTheProjectionOption) {
  expect_error([] { import_mesh(data / "quad_no_vt.obj"); }, "--uv-projection box|sphere|planar");
  import_options o;
  o.uvs = uv_projection::box;
  const imported_mesh im = import_mesh(data / "quad_no_vt.obj", o);
  EXPECT_EQ(im.model.triangles.size(), 2u);
  EXPECT_EQ(im.report.uvs, "box projection");
  // Box projection of the z-facing quad over its 2-unit extent: u = (x + 1)/2, v = (1 − y)/2.
  for (const vertex& v : im.model.vertices) {
    EXPECT_NEAR(v.uv.x, (v.position.x + 1.0f) / 2.0f, 1e-6f);
    EXPECT_NEAR(v.uv.y, (1.0f - v.position.y) / 2.0f, 1e-6f);
  }
  expect_frames(im.model);
}

TEST(MeshImport, NgonWithNegativeIndicesAndNoNormals) {
  for (normals_mode mode : {normals_mode::smooth, normals_mode::flat}) {
    import_options o;
    o.normals = mode;
    const imported_mesh im = import_mesh(data / "hexagon_negative.obj", o);
    EXPECT_EQ(im.model.triangles.size(), 4u);  // a hexagon fans into 6 − 2 triangles
    EXPECT_EQ(im.report.normals_generated, 6u);
    EXPECT_EQ(im.report.normals, mode == normals_mode::smooth ? "generated smooth (angle-weighted)" : "generated flat");
    for (const vertex& v : im.model.vertices) expect_near(v.normal, {0, 0, 1}, 1e-6f);  // counter-clockwise in xy
    expect_frames(im.model);
  }
}

TEST(MeshImport, ZeroAndNonUnitNormalsAreRepairedAndCounted) {
  const imported_mesh im = import_mesh(data / "grid_zero_normals.obj");
  EXPECT_EQ(im.model.triangles.size(), 18u);  // 3×3 quads
  EXPECT_EQ(im.report.normals_replaced, 3u);
  EXPECT_EQ(im.report.normals_renormalised, 1u);
  EXPECT_EQ(im.report.normals_generated, 0u);
  expect_frames(im.model);
}

TEST(MeshImport, CubeWithUvSeamsGetsSmoothNormalsAcrossTheSeams) {
  const imported_mesh smooth = import_mesh(data / "cube_seams.obj");
  EXPECT_EQ(smooth.model.triangles.size(), 12u);
  EXPECT_EQ(smooth.report.normals_generated, 8u);
  // Three faces meet at each corner with equal angles (π/2 each): the normal is the corner's diagonal.
  for (const vertex& v : smooth.model.vertices) expect_near(v.normal, glm::normalize(v.position), 1e-5f);
  import_options o;
  o.normals = normals_mode::flat;
  const imported_mesh flat = import_mesh(data / "cube_seams.obj", o);
  for (const auto& t : flat.model.triangles) {
    const glm::vec3 n = flat.model.vertices[t[0]].normal;
    EXPECT_NEAR(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z), 1.0f, 1e-6f);  // an axis
    const glm::vec3 centre =
        (flat.model.vertices[t[0]].position + flat.model.vertices[t[1]].position + flat.model.vertices[t[2]].position) /
        3.0f;
    EXPECT_GT(glm::dot(n, centre), 0.0f);  // outwards
  }
  expect_frames(flat.model);
}

TEST(MeshImport, MirroredUvsFlipTheTangentNotTheBitangent) {
  const imported_mesh im = import_mesh(data / "mirrored_strip.obj");
  ASSERT_EQ(im.model.triangles.size(), 4u);
  // Left quad: u along +x; right quad: u along −x. OBJ's v runs up (+y), so the renderer's v (down the
  // image) runs along −y on both: the bitangent is −y everywhere, the sign differs.
  for (std::size_t t = 0; t < 4; ++t) {
    const bool right = t >= 2;
    for (std::uint32_t i : im.model.triangles[t]) {
      expect_near(im.model.vertices[i].tangent, {right ? -1.0f : 1.0f, 0, 0}, 1e-6f);
      expect_near(im.model.vertices[i].bitangent, {0, -1, 0}, 1e-6f);
    }
  }
}

TEST(MeshImport, PointsAndLinesAreIgnoredWithACount) {
  const imported_mesh im = import_mesh(data / "points_lines.obj");
  EXPECT_EQ(im.model.triangles.size(), 2u);
  EXPECT_EQ(im.report.dropped_points, 1u);
  EXPECT_EQ(im.report.dropped_lines, 2u);
}

TEST(MeshImport, PlyTetrahedron) {
  const imported_mesh im = import_mesh(data / "tetrahedron.ply");
  EXPECT_EQ(im.model.triangles.size(), 4u);
  EXPECT_EQ(im.report.normals_generated, 4u);
  // A regular tetrahedron centred at the origin: each vertex normal points along the vertex.
  for (const vertex& v : im.model.vertices) expect_near(v.normal, glm::normalize(v.position), 1e-5f);
  expect_frames(im.model);
}

TEST(MeshImport, GlbWithEmbeddedNormalMapAndTangents) {
  const imported_mesh im = import_mesh(data / "mikk_mirrored.glb");
  EXPECT_EQ(im.model.triangles.size(), 124u);  // sphere 2·12·(6 − 1) + strip 4
  EXPECT_EQ(im.report.meshes, 2u);
  EXPECT_EQ(im.report.tangents, "file (TANGENT)");
  ASSERT_EQ(im.layers.maps.size(), 1u);  // both meshes' material names it: one layer, no flat one
  EXPECT_TRUE(im.layers.flat_materials.empty());
  EXPECT_TRUE(im.model.layer.empty());
  EXPECT_EQ(im.layers.maps[0].slot, "normal");
  ASSERT_GE(im.layers.maps[0].embedded.size(), 8u);
  EXPECT_EQ(im.layers.maps[0].embedded[1], 'P');  // \x89PNG
  expect_frames(im.model);
}

TEST(MeshImport, ZeroUvAreaTriangleGetsACountedFallbackFrame) {
  const fs::path d = gsdot3::test::fresh_temp_dir("gsdot3-mesh-import-flatuv");
  std::ofstream(d / "flatuv.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n";
  const imported_mesh im = import_mesh(d / "flatuv.obj");
  EXPECT_EQ(im.report.zero_uv_area_triangles, 1u);
  EXPECT_EQ(im.report.fallback_tangent_corners, 3u);
  for (const vertex& v : im.model.vertices) expect_near(v.tangent, {1, 0, 0}, 1e-6f);  // x, orthogonal to n = z
  fs::remove_all(d);
}

TEST(MeshImport, BadFilesGiveOneLineErrorsNamingTheFile) {
  expect_error([] { import_mesh(data / "missing.obj"); }, "missing.obj: cannot open the mesh");
  expect_error([] { import_mesh(data / "bad_nan.obj"); }, "bad_nan.obj: mesh 0: vertex 2 has a non-finite position");
  expect_error([] { import_mesh(data / "bad_empty.obj"); }, "bad_empty.obj: no triangles");
  expect_error([] { import_mesh(data / "bad_truncated.glb"); }, "bad_truncated.glb: cannot read the mesh");
  // An OFF header promising 2 faces with only 1 present makes assimp 5.2 abort (an ai_assert in its
  // triangulation): the import's child process dies, gsdot3 reports it.
  expect_error([] { import_mesh(data / "bad_off_face_count.off"); },
               "bad_off_face_count.off: the reader crashed (signal 6)");
  expect_error([] { import_mesh_from_memory("v 0 0 0\nvt 0 0\nf 1/1 2/1 3/1\n", "obj"); },
               "<memory>.obj: cannot read the mesh");
  expect_error([] { import_mesh_from_memory("v 0 0 0\nv 1 1 1\nv 2 2 2\nvt 0 0\nf 1/1 2/1 3/1\n", "obj"); },
               "no triangles");
  expect_error([] { import_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1e39 0\nvt 0 0\nf 1/1 2/1 3/1\n", "obj"); },
               "non-finite position");
  expect_error([] { import_mesh_from_memory("", "obj"); }, "cannot read the mesh");
}

}  // namespace
}  // namespace gsdot3::pipeline
