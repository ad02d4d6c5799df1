// pipeline/mesh_import.hpp — meshes as modelling tools export them (OBJ, glTF 2.0 / GLB, PLY, FBX,
// Collada, … whatever Debian's assimp 5.2 reads), turned into the renderer's mesh: every mesh of the
// file merged with its node transforms, triangulated, checked, repaired where a repair is well
// defined, with MikkTSpace tangents. Every repair is counted in the import report.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/files.hpp"
#include "pipeline/scene.hpp"

struct aiScene;  // <assimp/scene.h>

namespace gsdot3::pipeline {

enum class normals_mode { smooth, flat };                     // for meshes without normals
enum class uv_projection { automatic, box, sphere, planar };  // for meshes without UVs (uv_generation.hpp)
enum class tangent_mode { automatic, mikktspace };            // automatic: the file's tangents when it has them
enum class duplicates_mode { drop, keep };                    // triangles drawn twice (mesh_duplicates.hpp)

struct import_options {
  normals_mode normals = normals_mode::smooth;
  float crease_degrees = 60.0f;  // smooth: split across edges sharper than this (generated_normals.hpp)
  uv_projection uvs = uv_projection::automatic;
  tangent_mode tangents = tangent_mode::automatic;
  duplicates_mode duplicates = duplicates_mode::drop;
  // mesh-info: a file with no triangle to draw is described (an empty mesh, the reason in a notice)
  // instead of refused.
  bool describe_empty = false;
};

// A material's normal map: a file beside the mesh, or an image embedded in it (.glb).
struct texture_ref {
  std::string name;                    // as the mesh file names it
  std::filesystem::path file;          // resolved path of an external image (empty when embedded)
  std::vector<std::uint8_t> embedded;  // the encoded image (PNG, JPEG, TGA) when embedded
  image raw;                           // or its texels, when the file embeds them uncompressed
  std::string slot;                    // "normal" (glTF normalTexture, MTL norm) or "bump" (MTL bump, map_Bump)
  float scale = 1.0f;                  // glTF normalTexture.scale: x and y of the map's normals scaled
  unsigned uv_set = 0;                 // the texture-coordinate set it reads (glTF texCoord; assimp's UVWSRC)
  std::vector<std::string> materials;  // the drawn materials that name it
};

// The normal-map layers of a file's materials (scene.hpp's layers): one per distinct map (name, slot,
// scale, UV set) the drawn materials name, then, when some drawn material names none, a flat layer
// for those (a map whose every texel is (0, 0, 1), as an unmapped surface shades).
struct material_layers {
  std::vector<texture_ref> maps;            // layer k < maps.size(): maps[k]
  std::vector<std::string> flat_materials;  // the materials of the flat layer (empty: none)
  std::size_t count() const noexcept { return maps.size() + (flat_materials.empty() ? 0 : 1); }
};

// What was read and what was done to it (report.json "input", and one stderr line per notice).
struct import_report {
  std::string file, format;
  std::size_t meshes = 0, instances = 0, triangles = 0;  // source meshes, node instances, triangles kept
  std::size_t dropped_points = 0, dropped_lines = 0, dropped_degenerate = 0;
  std::size_t dropped_non_finite = 0;  // triangles with a vertex position NaN or infinite
  std::string normals = "file";        // file | generated smooth (… crease angle) | generated flat
  // Normal repairs, counted in distinct vertex positions:
  std::size_t normals_generated = 0;     // positions that had no normal in the file
  std::size_t normals_renormalised = 0;  // non-unit normals scaled to unit length
  std::size_t normals_replaced = 0;      // zero or NaN normals replaced by the generated smooth normal
  std::string uvs = "file";              // file | box, sphere or planar projection (automatic: why | --uv-projection)
  std::string tangents = "MikkTSpace (computed)";  // or "file (TANGENT)"
  std::size_t zero_uv_area_triangles = 0, fallback_tangent_corners = 0;
  std::size_t duplicate_triangles = 0;  // same positions and winding as an earlier triangle
  bool duplicates_dropped = true;       // import_options::duplicates
  std::vector<std::string> notices;     // one line each, in the order they arose
};

// At most this many layers: the report page numbers palette entries (256 a layer) in 16 bits.
inline constexpr std::size_t max_layers = 255;

// No material naming a map: one layer, of the map the scene gives (model.layer empty).
struct imported_mesh {
  mesh model;  // model.layer: per triangle, its material's layer of `layers`
  import_report report;
  material_layers layers;
};

// Reads a mesh file. Throws std::runtime_error "FILE: why" (one line) for an importer error, no
// triangles (none left once those with a NaN/Inf position are dropped) or out-of-range indices.
// The import runs in a child process with a 3 GiB address space and 120 s of CPU: an importer that
// crashes, runs out of memory or loops on a malformed file is an error, not the end (or the hang)
// of gsdot3 (child_process.hpp).
imported_mesh import_mesh(const std::filesystem::path& file, const import_options& options = {});

// The same from bytes in memory, also in a child process (the fuzz harness: assimp 5.2's OBJ
// reader writes to a wild address on some fuzzed files, a crash no gsdot3 code can prevent and the
// CLI survives the same way); `extension` ("obj", "glb", "ply", …) tells the importer the format.
imported_mesh import_mesh_from_memory(const std::string& bytes, const std::string& extension,
                                      const import_options& options = {});

// The conversion both imports run on the scene assimp read (in their child process), here in the
// calling process: every instanced mesh converted with its node transforms, repaired and merged, the
// material's normal map found (external names resolved against `dir`). Throws std::runtime_error
// "NAME: why" like import_mesh. For callers that build the scene themselves and run no parser
// (fuzz/mesh_from_scene.cpp); `format` goes into the report.
imported_mesh from_scene(const aiScene& scene, const std::string& name, const std::filesystem::path& dir,
                         const std::string& format, const import_options& options = {});

}  // namespace gsdot3::pipeline
