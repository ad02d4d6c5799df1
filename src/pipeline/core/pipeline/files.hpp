// pipeline/files.hpp — reading height maps (normal maps: normal_map_image.hpp; meshes: mesh_import.hpp) and
// writing PNG images. Every failure throws std::runtime_error with a one-line message naming the
// file; nothing is left half written (PNGs go to a temporary name and are renamed when complete).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
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

// A command's output folder, written completely or not at all: the files go into a fresh sibling
// folder (path()); commit() renames it to `target`, or, when `target` exists, renames each file into
// it (replacing the file of that name whole; the names in `last` at the end, e.g. the page whose
// presence says the report is complete). Files of `target` the run did not write are kept. Destroyed
// without commit() (an error, an exception), the sibling is removed and `target` is untouched.
// Throws std::runtime_error "TARGET: why" when the folder cannot be made or moved.
class staged_directory {
 public:
  explicit staged_directory(std::filesystem::path target);
  ~staged_directory();
  staged_directory(const staged_directory&) = delete;
  staged_directory& operator=(const staged_directory&) = delete;
  const std::filesystem::path& path() const noexcept { return staging_; }
  void commit(const std::vector<std::string>& last = {});

 private:
  std::filesystem::path target_, staging_;
  bool committed_ = false;
};

// The texels of an 8-bit PNG texture (power-of-two sides 8..1024, as the loaders above check): RGB
// (alpha stripped), or grey when `grey` is set and the file is grey. Used by `gsdot3 pvr-bump`.
image read_texture_image_png(const std::filesystem::path& file, bool grey);

}  // namespace gsdot3::pipeline
