// pipeline/asset_folder.hpp — the files a mesh may read: its own folder and what lies below it.
// glTF 2.0 resolves a URI relative to the file that holds it (glTF 2.0 specification, section 3.3
// "URIs": relative paths; data: URIs embed the bytes); a model downloaded from the web must not read
// /etc/passwd as vertex data or fetch from a server. Every file assimp opens goes through
// confined_io (Importer::SetIOHandler), and the material's normal-map file through inside_folder.
#pragma once

#include <filesystem>
#include <string>

#include <assimp/DefaultIOSystem.h>

namespace gsdot3::pipeline {

// The reason the path `reference` (as assimp composes it, "folder/" + the URI, or as the caller
// joins folder and a material's file name) may not be opened, or "" when it may: resolved as the
// operating system opens it (relative to the working directory, "a//b" as "a/b", ".." and symbolic
// links followed), it lies outside `folder`; or the name has a URI scheme ("http:", "file:"; data:
// URIs never reach a file system, the importer decodes them); or it is an absolute URI composed under
// the folder ("folder//etc/passwd") that names an existing file outside the folder (named as the URI
// gave it).
std::string outside_folder(const std::filesystem::path& folder, const std::string& reference);

// assimp's standard file access, refusing what outside_folder refuses. The first refused Open is kept
// so that the import's error names it (assimp's own message would only say a buffer was missing).
// An Exists outside the folder only answers "no": assimp's FileSystemFilter::Open, after a missing
// file (an OBJ's absent mtllib), probes "folder/" + pieces of the folder's own path, and such a piece
// can name an existing folder elsewhere ("folder//work/main"); the first such probe is kept in
// `probed`, which names the cause when the import fails (a glTF buffer assimp looked for first).
class confined_io : public Assimp::DefaultIOSystem {
 public:
  explicit confined_io(std::filesystem::path folder) : folder_(std::move(folder)) {}
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
  const std::string& refused() const noexcept { return refused_; }
  const std::string& probed() const noexcept { return probed_; }

 private:
  std::filesystem::path folder_;
  std::string refused_;
  mutable std::string probed_;
};

}  // namespace gsdot3::pipeline
