// Normal maps of several layers, one a material (scene.hpp, issue 54): a GS pixel reads only its own
// triangle's texels, so every pixel of a frame whose triangles sample two layers must equal the same
// pixel of the frame drawn with that triangle's layer's map on every triangle. The expected frames are
// the one-layer renderer's, the property is written without the layer code: every method, the value
// and memory paths, the scalar and SIMD pixels, 4-, 8- and 24-bit maps, bilinear, one draw buffer, at
// an odd size; the frame's dump replayed through gs_packets equals the memory path's frame; the float
// reference and a scheme per pixel alike.
// (Checked to fail: with each layer's triangle pass drawing layer 0's texture over every triangle, the
// frames and the dumps differ; with the dump's TEX0 naming layer 0's texture and CLUT for every layer,
// the dumps differ.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/temp_dir.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/files.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scene_input.hpp"
#include "pipeline/scheme_method.hpp"
#include "method_param.hpp"
#include "replayed_frame.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

struct scenes {
  scene both, first, second;  // both: the model's first half samples layer 0, the rest layer 1
};

scenes make_scenes(int bits) {
  scenes s;
  s.first = default_scene(64);
  s.first.width = 97, s.first.height = 71;
  s.second = s.first;
  s.second.normals = test::turned(s.first.normals);
  s.both = test::two_layers(s.first);
  for (scene* x : {&s.both, &s.first, &s.second}) x->normals = with_index_bits(x->normals, bits);
  return s;
}

// Pixel by pixel: frame `both` equals `first` where the visible triangle samples layer 0, `second` elsewhere.
void expect_composed(const frame& both, const frame& first, const frame& second, const prepared_scene& ps,
                     bool reads_map, const std::string& what) {
  ASSERT_EQ(both.visible_triangle, first.visible_triangle) << what;
  std::size_t wrong = 0, in_second = 0;
  for (std::size_t i = 0; i < both.colour.size(); ++i) {
    const std::int32_t t = both.visible_triangle[i];
    const bool layer1 = t >= 0 && ps.triangles[static_cast<std::size_t>(t)].layer == 1;
    in_second += layer1;
    wrong += both.colour[i] != (layer1 ? second : first).colour[i];
  }
  EXPECT_EQ(wrong, 0u) << what;
  EXPECT_GT(in_second, 200u) << what << ": layer 1 must cover part of the frame";
  if (reads_map) {
    EXPECT_NE(first.colour, second.colour) << what << ": the two maps must draw differently";
  } else {  // Gouraud shading (figure 6b) reads no normal map
    EXPECT_EQ(first.colour, second.colour) << what;
  }
}

class Layers : public ::testing::TestWithParam<method> {};

TEST_P(Layers, EveryPixelIsItsLayersFrame) {
  struct variant {
    const char* name;
    int bits;
    render_options o;
  };
  std::vector<variant> variants{
      {"value", 8, {}}, {"memory", 8, {}}, {"scalar", 8, {}}, {"bilinear 4-bit", 4, {}}, {"one buffer", 8, {}}};
  variants[1].o.memory_path = true;
  variants[2].o.simd = false;
  variants[3].o.bilinear = true;
  variants[3].o.memory_path = true;
  variants[4].o.buffers = draw_buffers::one;
  if (GetParam() == method::four_pass)
    variants.push_back({"24-bit memory", 24, {}}), variants.back().o.memory_path = true;
  for (const variant& v : variants) {
    const scenes s = make_scenes(v.bits);
    const prepared_scene ps = prepare(s.both);
    ASSERT_EQ(ps.layers.size(), 2u);
    expect_composed(render(s.both, ps, GetParam(), v.o), render(s.first, prepare(s.first), GetParam(), v.o),
                    render(s.second, prepare(s.second), GetParam(), v.o), ps, GetParam() != method::gouraud, v.name);
  }
}

// The dump: per layer TEX0 (its texture, its CLUT) before its triangles; replayed, the memory path's frame.
TEST_P(Layers, TheDumpReplaysToTheFrame) {
  const scenes s = make_scenes(8);
  const prepared_scene ps = prepare(s.both);
  render_options o;
  o.memory_path = true;
  const frame f = render(s.both, ps, GetParam(), o);
  const replayed_frame r = replay_frame(build_frame_packets(s.both, ps, GetParam(), o), o.model);
  EXPECT_EQ(r.colour, f.colour);
  const frame first = render(s.first, prepare(s.first), GetParam(), o);
  if (GetParam() != method::gouraud) { EXPECT_NE(r.colour, first.colour) << "the second layer must show in the dump"; }
}

INSTANTIATE_TEST_SUITE_P(GsMethods, Layers, ::testing::ValuesIn(gs_methods), method_param_name);

TEST(Layers, ReferenceAndSchemesReadTheTrianglesLayer) {
  const scenes s = make_scenes(8);
  const prepared_scene ps = prepare(s.both), p0 = prepare(s.first), p1 = prepare(s.second);
  render_options o;
  const std::vector<std::int32_t> visible = render(s.both, ps, method::two_pass, o).visible_triangle;
  // Per light and pixel: the value of `both` against the value of the visible triangle's layer's frame.
  auto check = [&](const std::vector<std::vector<float>>& both, const std::vector<std::vector<float>>& first,
                   const std::vector<std::vector<float>>& second, std::string_view what) {
    std::size_t wrong = 0, covered = 0, differ = 0;
    for (std::size_t i = 0; i < visible.size(); ++i) {
      if (visible[i] < 0) continue;
      ++covered;
      const bool layer1 = ps.triangles[static_cast<std::size_t>(visible[i])].layer == 1;
      for (std::size_t l = 0; l < both.size(); ++l) {
        wrong += both[l][i] != (layer1 ? second : first)[l][i];
        differ += first[l][i] != second[l][i];
      }
    }
    EXPECT_GT(covered, 1000u) << what;
    EXPECT_GT(differ, 100u) << what << ": the two maps must give different values";
    EXPECT_EQ(wrong, 0u) << what;
  };
  check(render_reference(s.both, ps, visible, false, 1.0, {}).renormalised,
        render_reference(s.first, p0, visible, false, 1.0, {}).renormalised,
        render_reference(s.second, p1, visible, false, 1.0, {}).renormalised, "reference");
  for (const scheme_method& m : scheme_methods())
    check(m.render(s.both, ps, visible, o).dot, m.render(s.first, p0, visible, o).dot,
          m.render(s.second, p1, visible, o).dot, m.name);
}

// A real asset (Debian's assimp-testmodels, scripts/setup): Khronos' ClearCoat test names two normal
// maps (RibsNormal on the BaseNorm and SharedNorm rows, PlasticWrap on one coating) and none for the
// labels and the other rows: three layers, and each pixel is the frame of its layer's map on every
// triangle — the labels the flat map's, without the ribs.
TEST(Layers, ClearCoatDrawsEachMaterialWithItsOwnMap) {
  const std::filesystem::path f = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not installed (Debian assimp-testmodels, scripts/setup)";
  scene_request r;
  r.mesh = f;
  r.width = 256, r.height = 224;
  const scene_input in = make_scene(r, [](const std::string&) {});
  ASSERT_EQ(layers(in.s.normals), 3u);
  ASSERT_EQ(in.summary.layers.size(), 3u);
  EXPECT_NE(in.summary.layers[0].find("RibsNormal.png"), std::string::npos) << in.summary.layers[0];
  EXPECT_NE(in.summary.layers[1].find("PlasticWrap_normals.jpg"), std::string::npos) << in.summary.layers[1];
  EXPECT_NE(in.summary.layers[2].find("LabelMaterial"), std::string::npos) << in.summary.layers[2];
  const prepared_scene ps = prepare(in.s);
  const frame both = render(in.s, ps, method::four_pass, {});
  std::array<frame, 3> alone;
  std::array<std::size_t, 3> pixels{}, wrong{}, differ{};
  for (std::size_t k = 0; k < 3; ++k) {
    scene one = in.s;
    one.normals = layer_map(in.s.normals, k);
    one.model.layer.clear();
    alone[k] = render(one, prepare(one), method::four_pass, {});
  }
  for (std::size_t i = 0; i < both.colour.size(); ++i) {
    if (both.visible_triangle[i] < 0) continue;
    const std::size_t k = ps.triangles[static_cast<std::size_t>(both.visible_triangle[i])].layer;
    ++pixels[k];
    wrong[k] += both.colour[i] != alone[k].colour[i];
    differ[k] += alone[0].colour[i] != alone[2].colour[i];
  }
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(pixels[k], 50u) << "layer " << k;
    EXPECT_EQ(wrong[k], 0u) << "layer " << k;
  }
  EXPECT_GT(differ[2], pixels[2] / 4) << "the ribs would show on the flat layer's pixels";
}

// glTF's normalTexture.scale and texCoord (a material's own map read as the material says): a triangle
// whose material's map reads TEXCOORD_1 with scale 0.5, the map one texel (218, 128, 218) = 45° from z
// in x. Expected: the vertices' UVs are TEXCOORD_1's (not TEXCOORD_0's single point), and the
// map's normal is normalize(0.5·x, 0.5·y, z) of the texel's (2c/255 − 1) — 26.6° from z, not 45°.
TEST(Layers, GltfNormalTextureScaleAndTexCoordAreRead) {
  const std::filesystem::path d = gsdot3::test::fresh_temp_dir("gsdot3-layers-gltf");
  const float data[] = {0,    0,    0,    1,    0,    0,    0, 1, 0,  // POSITION
                        0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f,           // TEXCOORD_0: one point
                        0,    0,    1,    0,    0,    1};             // TEXCOORD_1: the triangle
  std::ofstream(d / "t.bin", std::ios::binary).write(reinterpret_cast<const char*>(data), sizeof data);
  std::ofstream(d / "t.gltf") << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "buffers": [{"uri": "t.bin", "byteLength": 84}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                    {"buffer": 0, "byteOffset": 60, "byteLength": 24}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 2}, "material": 0}]}],
    "materials": [{"name": "M", "normalTexture": {"index": 0, "texCoord": 1, "scale": 0.5}}],
    "textures": [{"source": 0}], "images": [{"uri": "n.png"}]})";
  image texel{8, 8, 3, {}};
  for (int i = 0; i < 64; ++i) texel.data.insert(texel.data.end(), {218, 128, 218});
  write_png(d / "n.png", texel);
  scene_request r;
  r.mesh = d / "t.gltf";
  r.width = 32, r.height = 32;
  const scene_input in = make_scene(r, [](const std::string&) {});
  ASSERT_EQ(in.summary.layers.size(), 1u);
  EXPECT_NE(in.summary.layers[0].find("scale 0.5, UV set 1; materials: M"), std::string::npos) << in.summary.layers[0];
  std::vector<glm::vec2> uvs;
  for (const vertex& v : in.s.model.vertices) uvs.push_back(v.uv);
  std::sort(uvs.begin(), uvs.end(), [](glm::vec2 a, glm::vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  EXPECT_EQ(uvs, (std::vector<glm::vec2>{{0, 0}, {0, 1}, {1, 0}}));  // glTF's v runs down, as the renderer's
  const float c = 218 / 127.5f - 1, y = 128 / 127.5f - 1;
  const glm::vec3 want = glm::normalize(glm::vec3(0.5f * c, -0.5f * y, c));  // glTF's green points up the image
  ASSERT_FALSE(in.s.normals.unquantised.empty());
  EXPECT_LT(glm::length(in.s.normals.unquantised[0] - want), 1e-5f);
  EXPECT_NEAR(std::acos(static_cast<double>(in.s.normals.unquantised[0].z)) * 180 / 3.141592653589793, 26.6, 0.1);
  std::filesystem::remove_all(d);
}

TEST(Layers, LayersApartAndTogether) {
  const normal_map a = procedural_normal_map(16), b = test::turned(a);
  const normal_map m = stacked({a, b});
  ASSERT_EQ(layers(m), 2u);
  EXPECT_EQ(m.palette_start, (std::vector<std::uint32_t>{0, static_cast<std::uint32_t>(a.palette.size())}));
  for (std::size_t i = 0; i < layer_texels(m); ++i) {
    EXPECT_EQ(texel_normal(m, 0, i), a.palette[a.index[i]]);
    EXPECT_EQ(texel_normal(m, 1, i), b.palette[b.index[i]]);
  }
  const normal_map back = layer_map(m, 1);
  EXPECT_EQ(back.index, b.index);
  EXPECT_EQ(back.palette, b.palette);
  EXPECT_EQ(back.unquantised, b.unquantised);
  EXPECT_THROW(layer_map(m, 2), std::out_of_range);
  normal_map small = b;
  small.width = 8;
  EXPECT_THROW(stacked({a, small}), std::invalid_argument);
  const normal_map four = with_index_bits(m, 4);  // per layer: each its own 16 entries
  EXPECT_EQ(four.palette_start[1], with_index_bits(a, 4).palette.size());
}

TEST(Layers, ATriangleOfALayerTheMapLacksIsRefused) {
  scene s = default_scene(16);
  s.model.layer.assign(s.model.triangles.size(), 0);
  s.model.layer.back() = 1;
  EXPECT_THROW(prepare(s), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
