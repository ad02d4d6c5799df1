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

// A normal map made from an 8-bit grey height map PNG (a colour PNG is refused): central differences with
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

// A command's output folder, complete or untouched. The files go into a fresh sibling folder
// TARGET.partial-PID-N (path()); commit() puts it in place of `target`: swapped with an existing one in
// one rename (renameat2 RENAME_EXCHANGE; where the filesystem lacks it, the old folder is renamed aside
// first), then the old folder is removed, so `target` holds exactly the new run's files, never a merge.
// An existing `target` is replaced only if it is empty or a previous output (it holds `mark`, or the
// `.gsdot3-out` file every staged folder gets): otherwise the constructor refuses it, before any work.
// Destroyed without commit() (an error, an exception), the sibling is removed and `target` is untouched;
// so is it on SIGINT / SIGTERM / SIGHUP once remove_staging_on_signals() ran. The constructor also
// removes the siblings TARGET.partial-PID-... of processes that are gone (a crash, a kill -9).
// Throws std::runtime_error "TARGET: why" when the folder cannot be made or moved.
class staged_directory {
 public:
  staged_directory(std::filesystem::path target, const std::string& mark);
  ~staged_directory();
  staged_directory(const staged_directory&) = delete;
  staged_directory& operator=(const staged_directory&) = delete;
  const std::filesystem::path& path() const noexcept { return staging_; }
  // `message` with the staging folder's name replaced by the target's: what the user named.
  std::string as_target(std::string message) const;
  void commit();

 private:
  std::filesystem::path target_, staging_;
  int slot_ = -1;  // staging_signals.hpp
  bool committed_ = false;
};

// SIGINT, SIGTERM and SIGHUP remove every live staged_directory's folder, then end the process by the
// signal's default action (so its exit status names the signal). Call once, early in main; a signal
// ignored at the call (nohup, a background job of a non-interactive shell) stays ignored.
void remove_staging_on_signals();

// The texels of an 8-bit PNG texture (power-of-two sides 8..1024, as the loaders above check): RGB
// (alpha stripped), or, when `grey` is set, grey (a colour file is refused: a height map has one
// channel). Used by `gsdot3 pvr-bump`.
image read_texture_image_png(const std::filesystem::path& file, bool grey);

}  // namespace gsdot3::pipeline
