// pipeline/normal_map_image.hpp — a normal map from any image a user or a material gives: PNG,
// JPEG or TGA, any size (resampled to the GS's power-of-two sides up to 1024), either green-channel
// convention, quantised to the 256-entry palette.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "pipeline/files.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Which way the green channel points: up the image (OpenGL, glTF 2.0, Blender: "Y+") or down it
// (DirectX, Unreal, Source: "Y−"). The renderer's bitangent points down the image (v grows down).
enum class normal_map_y { up, down };

struct normal_map_settings {
  normal_map_y y = normal_map_y::up;  // glTF's convention
  bool grey_is_height = false;        // a grey image is a height map (an MTL bump) instead of an error
  float height_strength = 0.05f;      // slope per grey level for such a height map
  float xy_scale = 1.0f;              // x and y of every normal scaled, then renormalised (glTF normalTexture.scale)
  int width = 0, height = 0;          // the GS texture's sides (0: texture_side of the image's)
};

struct loaded_normal_map {
  normal_map map;
  std::string format;  // PNG, JPEG, TGA (or "texels" for raw embedded ones)
  int source_width = 0, source_height = 0;
  bool resampled = false, from_height = false;
};

// The filter used when the size is not a GS texture size, as stated in notices and the report.
inline constexpr const char* resample_filter =
    "box (area-weighted mean of the unit normals each texel covers, renormalised)";

// The GS side for an image side: the power of two nearest in log scale, clamped to 8..1024.
int texture_side(int side);

// Box-filter resampling of a w×h field of unit normals to W×H.
std::vector<glm::vec3> resample_normals(const std::vector<glm::vec3>& n, int w, int h, int W, int H);

loaded_normal_map normal_map_from_image(const image& img, const std::string& name, const normal_map_settings& s);
loaded_normal_map load_normal_map(const std::uint8_t* data, std::size_t size, const std::string& name,
                                  const normal_map_settings& s);
loaded_normal_map load_normal_map(const std::filesystem::path& file, const normal_map_settings& s);

}  // namespace gsdot3::pipeline
