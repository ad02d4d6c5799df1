// What a mesh may read (pipeline/asset_folder.hpp) and how a command's output folder appears
// (pipeline/files.hpp staged_directory). The glTF files are written here: a triangle whose buffer
// is named by an absolute path, a ".." escape, an http: URI, a relative path and a data: URI.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "common/temp_dir.hpp"
#include "expect_error.hpp"
#include "pipeline/asset_folder.hpp"
#include "pipeline/files.hpp"
#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;
using test::expect_error;

// Three positions and three UVs as little-endian floats (x86): 60 bytes.
std::string triangle_bytes() {
  const float f[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
  return std::string(reinterpret_cast<const char*>(f), sizeof f);
}

std::string base64(const std::string& in) {  // RFC 4648, written for this test
  static const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    unsigned v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= static_cast<unsigned char>(in[i + 2]);
    out += a[(v >> 18) & 63];
    out += a[(v >> 12) & 63];
    out += i + 1 < in.size() ? a[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? a[v & 63] : '=';
  }
  return out;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string gltf(const std::string& uri) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1}}]}],)"
         R"("buffers":[{"uri":")" +
         uri +
         R"(","byteLength":60}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
         R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}]})";
}

TEST(AssetFolder, GltfBuffersOutsideTheFilesFolderAreRefused) {
  const fs::path dir = gsdot3::test::fresh_temp_dir("gsdot3-asset-folder");
  write(dir / "outside.bin", triangle_bytes());
  write(dir / "model" / "inside.bin", triangle_bytes());
  write(dir / "model" / "relative.gltf", gltf("inside.bin"));
  write(dir / "model" / "data.gltf", gltf("data:application/octet-stream;base64," + base64(triangle_bytes())));
  write(dir / "model" / "absolute.gltf", gltf((dir / "outside.bin").string()));
  write(dir / "model" / "dotdot.gltf", gltf("../outside.bin"));
  write(dir / "model" / "deeper_dotdot.gltf", gltf("sub/../../outside.bin"));
  write(dir / "model" / "http.gltf", gltf("http://example.invalid/inside.bin"));

  EXPECT_EQ(import_mesh(dir / "model" / "relative.gltf").model.triangles.size(), 1u);
  EXPECT_EQ(import_mesh(dir / "model" / "data.gltf").model.triangles.size(), 1u);
  for (const char* f : {"dotdot.gltf", "deeper_dotdot.gltf"})
    expect_error([&] { import_mesh(dir / "model" / f); }, "outside the file's folder");
  // assimp composes "model//DIR/outside.bin", which is looked for below model/ and is not there.
  expect_error([&] { import_mesh(dir / "model" / "absolute.gltf"); }, "could not open referenced file");
  expect_error([&] { import_mesh(dir / "model" / "http.gltf"); }, "URI scheme (http:)");
  fs::remove_all(dir);
}

TEST(AssetFolder, OutsideFolderJudgesTheResolvedPath) {
  const fs::path dir = gsdot3::test::fresh_temp_dir("gsdot3-asset-folder");
  fs::create_directories(dir / "m" / "maps");
  const std::string m = (dir / "m").string();
  EXPECT_EQ(outside_folder(dir / "m", m + "/maps/n.png"), "");
  EXPECT_EQ(outside_folder(dir / "m", m + "/maps/../n.png"), "");  // still inside
  EXPECT_EQ(outside_folder(dir / "m", m + "//etc/passwd"), "");    // opened as m/etc/passwd
  EXPECT_NE(outside_folder(dir / "m", m + "/../n.png"), "");
  EXPECT_NE(outside_folder(dir / "m", "/etc/passwd"), "");
  EXPECT_NE(outside_folder(dir / "m", m + "/file:///etc/passwd"), "");
  EXPECT_NE(outside_folder(dir / "m", m + "/C:/textures/n.png"), "");
  fs::create_directory_symlink("/etc", dir / "m" / "link");  // a link out of the folder is outside
  EXPECT_NE(outside_folder(dir / "m", m + "/link/passwd"), "");
  fs::remove_all(dir);
}

TEST(StagedDirectory, NothingAppearsUnlessCommitted) {
  const fs::path dir = gsdot3::test::fresh_temp_dir("gsdot3-staged");
  const fs::path out = dir / "out";
  {
    staged_directory s(out);
    write(s.path() / "a.png", "half");
    EXPECT_FALSE(fs::exists(out));
  }  // an error before commit
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(dir)) << "the staging folder was left behind";
  {
    staged_directory s(out);
    write(s.path() / "a.png", "new");
    s.commit();
  }
  std::ifstream in(out / "a.png");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "new");
  fs::remove_all(dir);
}

TEST(StagedDirectory, AnExistingFolderKeepsWhatTheRunDidNotWrite) {
  const fs::path dir = gsdot3::test::fresh_temp_dir("gsdot3-staged");
  const fs::path out = dir / "out";
  write(out / "notes.txt", "mine");
  write(out / "a.png", "old");
  {
    staged_directory s(out);
    write(s.path() / "a.png", "new");
    write(s.path() / "report.html", "page");
    s.commit({"report.html"});
  }
  std::string a, notes;
  std::ifstream(out / "a.png") >> a;
  std::ifstream(out / "notes.txt") >> notes;
  EXPECT_EQ(a, "new");
  EXPECT_EQ(notes, "mine");
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
      << "a staging folder was left behind";
  write(dir / "file", "x");
  EXPECT_THROW(staged_directory(dir / "file"), std::runtime_error);  // not a directory
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gsdot3::pipeline
