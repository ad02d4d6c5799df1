// pipeline/files.hpp — reading height maps (normal maps: normal_map_image.hpp; meshes: mesh_import.hpp) and
// writing PNG images. Every failure throws std::runtime_error with a one-line message naming the
// file; nothing is left half written (PNGs go to a temporary name and are renamed when complete).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// A normal map made from an 8-bit grey (or RGB: red) height map PNG: central differences with
// slopes scaled by `strength` (height units: grey levels), then quantised to 256 entries.
normal_map load_height_map_png(const std::filesystem::path& file, float strength);

// An 8-bit image: `channels` = 1 (grey) or 3 (RGB), rows top first.
struct image {
  int width = 0, height = 0, channels = 3;
  std::vector<std::uint8_t> data;
};
void write_png(const std::filesystem::path& file, const image& img);

// Writes `bytes` to FILE.tmp and renames it to FILE, so a reader never sees half a file; throws
// std::runtime_error "FILE: why" (the temporary is removed) when either step fails.
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

// The texels of an 8-bit PNG texture (power-of-two sides 8..1024, as the loaders above check): RGB
// (alpha stripped), or grey when `grey` is set and the file is grey. Used by `gsdot3 pvr-bump`.
image read_texture_image_png(const std::filesystem::path& file, bool grey);

}  // namespace gsdot3::pipeline
