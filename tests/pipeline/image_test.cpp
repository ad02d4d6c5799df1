// Normal maps from images: the formats (PNG by libpng, JPEG by libjpeg-turbo, TGA by stb_image), the green-channel
// convention, resampling to GS sizes, materials' maps found from a mesh, and hostile headers. The
// image fixtures were written with stb_image_write (tests/data/README.md); expected normals follow
// from the bytes written, n = rgb/127.5 − 1.
#include <gtest/gtest.h>

#include "expect_error.hpp"

#include <cmath>
#include <filesystem>
#include <functional>

#include <glm/geometric.hpp>
#include <png.h>

#include "pipeline/image_io.hpp"
#include "pipeline/mesh_import.hpp"
#include "pipeline/normal_map_image.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;
const fs::path meshes = fs::path(GSDOT3_TEST_DATA) / "meshes";
const fs::path images = fs::path(GSDOT3_TEST_DATA) / "images";

using test::expect_error;

glm::vec3 texel(const normal_map& m, int x, int y) {
  return m.palette[m.index[static_cast<std::size_t>(y * m.width + x)]];
}

TEST(NormalMapImage, TgaAndTheGreenConvention) {
  // Every texel (128, 200, 200): green up the image is −y in the renderer's frame (v runs down).
  const glm::vec3 raw = glm::normalize(glm::vec3(128 / 127.5f - 1, 200 / 127.5f - 1, 200 / 127.5f - 1));
  normal_map_settings s;
  const loaded_normal_map up = load_normal_map(meshes / "tilt_green.tga", s);
  s.y = normal_map_y::down;
  const loaded_normal_map down = load_normal_map(meshes / "tilt_green.tga", s);
  EXPECT_EQ(up.format, "TGA");
  ASSERT_EQ(up.map.palette.size(), 1u);
  ASSERT_EQ(down.map.palette.size(), 1u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(up.map.palette[0][i], i == 1 ? -raw[i] : raw[i], 1e-6f);
    EXPECT_NEAR(down.map.palette[0][i], raw[i], 1e-6f);
  }
  EXPECT_FALSE(up.resampled);
}

TEST(NormalMapImage, JpegOfOddSizeIsResampled) {
  const loaded_normal_map m = load_normal_map(meshes / "halves_24x20.jpg", {});
  EXPECT_EQ(m.format, "JPEG");
  EXPECT_TRUE(m.resampled);
  EXPECT_EQ(m.map.width, 32);   // 2^round(log2 24) = 2^5
  EXPECT_EQ(m.map.height, 16);  // 2^round(log2 20) = 2^4
  // Left half written as (200, 128, 200), right half as (128, 128, 255); JPEG loses a little.
  const glm::vec3 left = glm::normalize(glm::vec3(200 / 127.5f - 1, 0, 200 / 127.5f - 1));
  EXPECT_GT(glm::dot(texel(m.map, 3, 8), left), 0.995f);
  EXPECT_GT(glm::dot(texel(m.map, 28, 8), glm::vec3(0, 0, 1)), 0.995f);
}

TEST(NormalMapImage, TextureSideIsTheNearestPowerOfTwoInLogScale) {
  // 2^round(log2 n), clamped to 8..1024; 724 < 512·√2 ≈ 724.08 < 725.
  const std::pair<int, int> cases[] = {{1, 8},     {8, 8},      {11, 8},      {12, 16},    {100, 128},
                                       {724, 512}, {725, 1024}, {1024, 1024}, {4096, 1024}};
  for (const auto& [in, out] : cases) EXPECT_EQ(texture_side(in), out) << in;
}

TEST(NormalMapImage, BoxResamplingAveragesCoveredTexels) {
  // 16×16 → 8×8: each output texel is the renormalised mean of a 2×2 block.
  std::vector<glm::vec3> n(256);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      n[static_cast<std::size_t>(y * 16 + x)] = (x + y) % 2 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  const auto down = resample_normals(n, 16, 16, 8, 8);
  for (const glm::vec3& v : down) {
    EXPECT_NEAR(v.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(v.z, std::sqrt(0.5f), 1e-6f);
  }
  // 3×1 → 8×1 (upsampling): output texel i covers [3i/8, 3(i+1)/8) of the source.
  const std::vector<glm::vec3> row = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto up = resample_normals(row, 3, 1, 8, 1);
  EXPECT_EQ(up[0], glm::vec3(1, 0, 0));  // [0, 0.375)
  EXPECT_NEAR(up[2].x, 1 / std::sqrt(1.0f + (0.125f / 0.25f) * (0.125f / 0.25f)),
              1e-6f);  // [0.75, 1.125): 0.25 x, 0.125 y
  EXPECT_EQ(up[7], glm::vec3(0, 0, 1));
}

TEST(NormalMapImage, MaterialsNameTheirNormalMaps) {
  const imported_mesh norm = import_mesh(meshes / "quad_norm.obj");
  ASSERT_EQ(norm.layers.maps.size(), 1u);
  EXPECT_EQ(norm.layers.maps[0].slot, "normal");  // MTL norm
  EXPECT_EQ(norm.layers.maps[0].file.filename(), "tilt_green.tga");
  const imported_mesh bump = import_mesh(meshes / "quad_bump.obj");
  ASSERT_EQ(bump.layers.maps.size(), 1u);
  EXPECT_EQ(bump.layers.maps[0].slot, "bump");  // MTL map_Bump
  EXPECT_EQ(bump.layers.maps[0].file.filename(), "halves_24x20.jpg");
  const imported_mesh height = import_mesh(meshes / "quad_height.obj");
  ASSERT_EQ(height.layers.maps.size(), 1u);
  normal_map_settings s;
  s.grey_is_height = true;
  const loaded_normal_map h = load_normal_map(height.layers.maps[0].file, s);
  EXPECT_TRUE(h.from_height);                                               // a grey bump image is a height map
  EXPECT_TRUE(import_mesh(meshes / "cube_seams.obj").layers.maps.empty());  // its .mtl is missing
}

TEST(NormalMapImage, GlbEmbeddedNormalMapDecodes) {
  const imported_mesh im = import_mesh(meshes / "mikk_mirrored.glb");
  ASSERT_EQ(im.layers.maps.size(), 1u);
  const auto& e = im.layers.maps[0].embedded;
  const loaded_normal_map m = load_normal_map(e.data(), e.size(), "embedded", {});
  EXPECT_EQ(m.format, "PNG");
  EXPECT_EQ(m.map.width, 16);
  // The centred bump (gen.mjs): the texel right of centre leans +x; below centre, green < 128 in the
  // file (leaning down the image) is +y in the renderer's v-down frame.
  EXPECT_GT(texel(m.map, 14, 8).x, 0.3f);
  EXPECT_GT(texel(m.map, 8, 14).y, 0.3f);
}

TEST(NormalMapImage, HostileImagesGiveOneLineErrors) {
  expect_error([] { load_normal_map(images / "huge_header.png", {}); }, "the image is 65536x65536; at most 16384");
  expect_error([] { load_normal_map(images / "huge_header.tga", {}); }, "huge_header.tga: ");
  // A cut or overrunning RLE stream (16×16, 24-bit; written by hand, see tests/data/README.md) is
  // refused, not decoded with zeros: cut_rle.tga holds one run of 3 pixels and ends.
  expect_error([] { load_normal_map(images / "cut_rle.tga", {}); },
               "cut_rle.tga: the TGA's RLE stream ends after 3 of 256 pixels");
  // overrun_rle.tga's four 128-pixel runs cover the 256 pixels twice: what follows the first two is
  // trailing data, as a TGA 2.0 file's extension area and footer are, so the map decodes (all 0xc8c880).
  const loaded_normal_map over = load_normal_map(images / "overrun_rle.tga", {});
  EXPECT_EQ(over.map.index.size(), 256u);
  EXPECT_EQ(over.map.palette.size(), 1u);
}

// A PNG written by libpng's simplified API (png_image) from 5x3 pixels of `format`.
std::vector<std::uint8_t> encode_png(png_uint_32 format, const std::vector<std::uint8_t>& pixels,
                                     const std::uint8_t* colormap) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  img.width = 5;
  img.height = 3;
  img.format = format;
  img.colormap_entries = colormap != nullptr ? 4 : 0;
  png_alloc_size_t size = 0;
  EXPECT_TRUE(png_image_write_to_memory(&img, nullptr, &size, 0, pixels.data(), 0, colormap)) << img.message;
  std::vector<std::uint8_t> out(size);
  EXPECT_TRUE(png_image_write_to_memory(&img, out.data(), &size, 0, pixels.data(), 0, colormap)) << img.message;
  out.resize(size);
  return out;
}

// decode_png_rgba equals libpng's simplified reader (png_image to PNG_FORMAT_RGBA: its own
// transformation code, and gsdot3's RGBA reader before image_io had one) in texels and flags, on
// 8-bit files of every colour type: grey, grey + alpha, RGB, RGBA, a palette with tRNS.
TEST(PngRgba, AgreesWithLibpngsSimplifiedReader) {
  std::vector<std::uint8_t> values(5 * 3 * 4), indices(5 * 3);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::uint8_t>(37 * i + 11);
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint8_t>(i % 4);
  const std::uint8_t colormap[16] = {200, 10, 30, 255, 0, 90, 250, 0, 60, 60, 61, 128, 255, 255, 255, 255};
  for (const png_uint_32 format : std::initializer_list<png_uint_32>{PNG_FORMAT_GRAY, PNG_FORMAT_GA, PNG_FORMAT_RGB,
                                                                     PNG_FORMAT_RGBA, PNG_FORMAT_RGBA_COLORMAP}) {
    const bool mapped = (format & PNG_FORMAT_FLAG_COLORMAP) != 0;
    const std::vector<std::uint8_t> file = encode_png(format, mapped ? indices : values, mapped ? colormap : nullptr);
    const rgba_image got = decode_png_rgba(file.data(), file.size(), "test.png");

    png_image ref{};
    ref.version = PNG_IMAGE_VERSION;
    ASSERT_TRUE(png_image_begin_read_from_memory(&ref, file.data(), file.size())) << ref.message;
    const bool alpha = (ref.format & PNG_FORMAT_FLAG_ALPHA) != 0, grey = (ref.format & PNG_FORMAT_FLAG_COLOR) == 0;
    ref.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> want(PNG_IMAGE_SIZE(ref));
    ASSERT_TRUE(png_image_finish_read(&ref, nullptr, want.data(), 0, nullptr)) << ref.message;
    png_image_free(&ref);

    EXPECT_EQ(got.width, 5) << format;
    EXPECT_EQ(got.height, 3) << format;
    EXPECT_EQ(got.rgba, want) << format;
    EXPECT_EQ(got.has_alpha, alpha) << format;
    EXPECT_EQ(got.grey, grey) << format;
  }
  expect_error([] { read_png_rgba(images / "huge_header.png"); }, "the image is 65536x65536; at most 16384");
}

}  // namespace
}  // namespace gsdot3::pipeline
