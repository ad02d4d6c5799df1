// Bad input: each case fails with a one-line message naming the problem, and leaves no report.
#include <gtest/gtest.h>

#include "expect_error.hpp"

#include <filesystem>
#include <fstream>
#include <functional>

#include <glm/geometric.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/files.hpp"
#include "pipeline/mesh_import.hpp"
#include "pipeline/normal_map_image.hpp"
#include "pipeline/report.hpp"
#include "common/temp_dir.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  return gsdot3::test::fresh_temp_dir(std::string("gsdot3-pipeline-test-") +
                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

using test::expect_error;

const std::string good_quad =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
    "f 1/1/1 2/2/1 3/3/1 4/4/1\n";

// The OBJ cases of the hand-written parser this replaced, through assimp: each bad file is still a
// one-line error naming the file (the wording of assimp's own errors is assimp's).
TEST(BadInput, Obj) {
  const fs::path d = temp_dir();
  expect_error([&] { import_mesh(d / "missing.obj"); }, "cannot open the mesh");
  expect_error([&] { import_mesh(write(d, "nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n")); },
               "non-finite position");
  expect_error([&] { import_mesh(write(d, "word.obj", "v 0 zero 0\nf 1 2 3\n")); }, "word.obj: ");
  expect_error([&] { import_mesh(write(d, "short.obj", "v 0 0\nf 1 1 1\n")); }, "short.obj: ");
  expect_error([&] { import_mesh(write(d, "index.obj", "v 0 0 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n")); },
               "index.obj: ");
  // No UVs is no longer an error (issue 54): the triangle, flat in z, is planar-projected.
  EXPECT_EQ(import_mesh(write(d, "nouv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"))
                .report.uvs.rfind("planar projection (chosen for the shape", 0),
            0u);
  expect_error([&] { import_mesh(write(d, "empty.obj", "# nothing\n")); }, "empty.obj: ");
  expect_error(
      [&] {
        import_mesh(write(d, "degenerate.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"));
      },
      "no triangles");
  EXPECT_EQ(import_mesh(write(d, "good.obj", good_quad)).model.triangles.size(), 2u);
  fs::remove_all(d);
}

TEST(BadInput, NormalMapPng) {
  const fs::path d = temp_dir();
  const normal_map_settings nms;
  expect_error([&] { load_normal_map(d / "missing.png", nms); }, "cannot open the normal map");
  expect_error([&] { load_normal_map(write(d, "text.png", "not a png at all"), nms); }, "not a PNG, JPEG or TGA image");
  // A valid PNG of a size the GS has no texture for is resampled (to the powers of two nearest in
  // log scale: 100 → 128, 60 → 64); a truncated one is an error.
  image img{100, 60, 3, std::vector<std::uint8_t>(100 * 60 * 3, 128)};
  write_png(d / "odd.png", img);
  const loaded_normal_map odd = load_normal_map(d / "odd.png", nms);
  EXPECT_TRUE(odd.resampled);
  EXPECT_EQ(odd.map.width, 128);
  EXPECT_EQ(odd.map.height, 64);
  image grey{16, 16, 1, std::vector<std::uint8_t>(256, 128)};
  write_png(d / "grey.png", grey);
  expect_error([&] { load_normal_map(d / "grey.png", nms); }, "must be 8-bit RGB");
  image ok{16, 16, 3, std::vector<std::uint8_t>(16 * 16 * 3, 128)};
  for (std::size_t i = 2; i < ok.data.size(); i += 3) ok.data[i] = 255;
  write_png(d / "ok.png", ok);
  {
    std::ifstream in(d / "ok.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    write(d, "cut.png", bytes.substr(0, bytes.size() / 2));
  }
  expect_error([&] { load_normal_map(d / "cut.png", nms); }, "malformed PNG data");
  // A grey ramp as a height map: x slopes only, so every normal leans the same way in x (−x: uphill
  // to +x) and not at all in y, except where the ramp wraps back at the border.
  image ramp{16, 16, 1, std::vector<std::uint8_t>(256)};
  for (std::size_t i = 0; i < 256; ++i) ramp.data[i] = static_cast<std::uint8_t>((i % 16) * 8);
  write_png(d / "ramp.png", ramp);
  const normal_map hm = load_height_map_png(d / "ramp.png", 0.1f);
  const glm::vec3 inner = hm.palette[hm.index[16 * 5 + 7]];
  EXPECT_LT(inner.x, -0.3f);
  EXPECT_NEAR(inner.y, 0.0f, 1e-5f);
  expect_error([&] { load_height_map_png(d / "odd.png", 1.0f); }, "must be powers of two");
  const normal_map m = load_normal_map(d / "ok.png", nms).map;
  EXPECT_EQ(m.width, 16);
  ASSERT_EQ(m.palette.size(), 1u);
  EXPECT_NEAR(m.palette[0].z, 1.0f, 1e-2f);
  fs::remove_all(d);
}

TEST(BadInput, UnwritableOutputLeavesNoReport) {
  const fs::path d = temp_dir();
  const fs::path file = write(d, "a-file", "x");
  scene s = default_scene(16);
  s.width = 32;
  s.height = 32;
  report_request r;
  r.out_dir = file / "sub";
  expect_error([&] { write_report(s, r); }, "cannot create the output directory");
  EXPECT_FALSE(fs::exists(file / "sub" / "report.html"));
  fs::remove_all(d);
}

TEST(Report, WritesHtmlLastAndReplacesAnOldOne) {
  const fs::path d = temp_dir();
  scene s = default_scene(16);
  s.width = 64;
  s.height = 56;
  report_request r;
  r.out_dir = d;
  const report_summary sum = write_report(s, r);
  EXPECT_TRUE(fs::exists(sum.html));
  EXPECT_TRUE(fs::exists(sum.json));
  EXPECT_TRUE(fs::exists(d / "side-by-side.png"));
  for (const auto& e : fs::directory_iterator(d)) EXPECT_NE(e.path().extension(), ".tmp") << e.path();
  ASSERT_EQ(sum.methods.size(), std::size(gs_methods));
  for (const auto& m : sum.methods) EXPECT_GT(m.vs_renormalised.samples, 0u);
  fs::remove_all(d);
}

TEST(Mesh, DegenerateUvStillGivesUnitOrthogonalTangents) {
  const fs::path d = temp_dir();
  const mesh m =
      import_mesh(write(d, "flatuv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"))
          .model;
  for (const vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
  }
  fs::remove_all(d);
}

}  // namespace
}  // namespace gsdot3::pipeline
