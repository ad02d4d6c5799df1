// pipeline/mesh_import.cpp — assimp's scene to source meshes and instances (mesh_repair.hpp), and
// the material's normal map. Files are imported in a child process (child_process.hpp).
#include "pipeline/mesh_import.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/commonMetaData.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "pipeline/asset_folder.hpp"
#include "pipeline/child_process.hpp"
#include "pipeline/material_layers.hpp"
#include "pipeline/mesh_repair.hpp"

namespace gsdot3::pipeline {

namespace {

// Triangulate n-gons; nothing else: normals, UVs and tangents are gsdot3's business (and counted).
constexpr unsigned import_flags = aiProcess_Triangulate;

glm::mat4 to_glm(const aiMatrix4x4& m) {  // assimp is row-major (a4, b4, c4: translation)
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

glm::vec3 v3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// Mesh `index`, its UVs from set `uv_set` (its material's normal map's; set 0 when it lacks that set).
source_mesh convert(const aiMesh& am, std::size_t index, unsigned uv_set, import_report& report) {
  source_mesh m;
  const std::string which = "mesh " + std::to_string(index);
  if (am.mVertices == nullptr && am.mNumVertices > 0) throw std::runtime_error(which + " has no positions");
  m.positions.reserve(am.mNumVertices);
  std::vector<char> non_finite(am.mNumVertices, 0);  // its triangles are dropped, and it is never read
  for (unsigned i = 0; i < am.mNumVertices; ++i) {
    const glm::vec3 p = v3(am.mVertices[i]);
    non_finite[i] = !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z);
    m.positions.push_back(non_finite[i] ? glm::vec3(0.0f) : p);
  }
  if (am.mNormals != nullptr)
    for (unsigned i = 0; i < am.mNumVertices; ++i) m.normals.push_back(v3(am.mNormals[i]));
  const aiVector3D* uv = uv_set < AI_MAX_NUMBER_OF_TEXTURECOORDS && am.mTextureCoords[uv_set] != nullptr
                             ? am.mTextureCoords[uv_set]
                             : am.mTextureCoords[0];
  if (uv != nullptr)  // assimp: v runs up the image; the renderer's v runs down
    for (unsigned i = 0; i < am.mNumVertices; ++i) m.uvs.push_back({uv[i].x, 1.0f - uv[i].y});
  if (am.mTangents != nullptr && am.mBitangents != nullptr)
    for (unsigned i = 0; i < am.mNumVertices; ++i) {
      m.tangents.push_back(v3(am.mTangents[i]));
      m.bitangents.push_back(v3(am.mBitangents[i]));
    }
  for (unsigned f = 0; f < am.mNumFaces; ++f) {
    const aiFace& face = am.mFaces[f];
    if (face.mNumIndices == 1) ++report.dropped_points;
    if (face.mNumIndices == 2) ++report.dropped_lines;
    if (face.mNumIndices < 3) continue;
    for (unsigned k = 0; k < face.mNumIndices; ++k)
      if (face.mIndices[k] >= am.mNumVertices)
        throw std::runtime_error(which + ": face " + std::to_string(f) + " refers to vertex " +
                                 std::to_string(face.mIndices[k]) + " of " + std::to_string(am.mNumVertices));
    if (std::any_of(face.mIndices, face.mIndices + face.mNumIndices, [&](unsigned v) { return non_finite[v]; })) {
      report.dropped_non_finite += face.mNumIndices - 2;
      continue;
    }
    for (unsigned k = 1; k + 1 < face.mNumIndices; ++k)  // a polygon the triangulation left: a fan
      m.triangles.push_back({face.mIndices[0], face.mIndices[k], face.mIndices[k + 1]});
  }
  return m;
}

// Every node's meshes with the node's accumulated transform (iteratively: hostile files nest deeply).
std::vector<source_instance> instances_of(const aiScene& s) {
  std::vector<source_instance> out;
  std::vector<std::pair<const aiNode*, glm::mat4>> pending;
  if (s.mRootNode != nullptr) pending.push_back({s.mRootNode, glm::mat4(1.0f)});
  while (!pending.empty()) {
    const auto [node, parent] = pending.back();
    pending.pop_back();
    const glm::mat4 t = parent * to_glm(node->mTransformation);
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      if (node->mMeshes[i] < s.mNumMeshes) out.push_back({node->mMeshes[i], t});
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      if (node->mChildren[c] != nullptr) pending.push_back({node->mChildren[c], t});
  }
  return out;
}

// The scene the importer read, or its error as "NAME: cannot read the mesh (why)".
const aiScene& scene_or_error(const aiScene* s, const Assimp::Importer& imp, const std::string& name) {
  if (s != nullptr) return *s;
  std::string why = imp.GetErrorString();
  std::replace(why.begin(), why.end(), '\n', ' ');
  throw std::runtime_error(name + ": cannot read the mesh (" + (why.empty() ? std::string("unknown format") : why) +
                           ")");
}

// The importer that read the scene, as assimp records it (AI_METADATA_SOURCE_FORMAT); else the extension.
std::string format_of(const aiScene* s, const std::string& extension) {
  aiString f;
  if (s != nullptr && s->mMetaData != nullptr && s->mMetaData->Get(AI_METADATA_SOURCE_FORMAT, f) && f.length > 0)
    return f.C_Str();
  return extension;
}

// The child's result as bytes: PODs copied, strings and vectors with their lengths in front.
struct writer {
  std::string out;
  template <class T>
  void pod(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void text(const std::string& t) {
    pod(t.size());
    out += t;
  }
  template <class T>
  void pods(const std::vector<T>& v) {
    pod(v.size());
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

struct reader {
  const std::string& in;
  std::size_t at = 0;
  void take(void* to, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null
    if (n > in.size() - at) throw std::runtime_error("the reader process returned a short result");
    std::memcpy(to, in.data() + at, n);
    at += n;
  }
  template <class T>
  T pod() {
    T v{};
    take(&v, sizeof v);
    return v;
  }
  std::string text() {
    std::string t(std::min(pod<std::size_t>(), in.size() - at), '\0');
    take(t.data(), t.size());
    return t;
  }
  template <class T>
  std::vector<T> pods() {
    std::vector<T> v(std::min(pod<std::size_t>(), (in.size() - at) / sizeof(T)));
    take(v.data(), v.size() * sizeof(T));
    return v;
  }
};

std::string serialise(const imported_mesh& m) {
  writer w;
  w.pods(m.model.vertices);
  w.pods(m.model.triangles);
  w.pods(m.model.layer);
  const import_report& r = m.report;
  for (const std::string* t : {&r.file, &r.format, &r.normals, &r.uvs, &r.tangents}) w.text(*t);
  for (std::size_t n : {r.meshes, r.instances, r.triangles, r.dropped_points, r.dropped_lines, r.dropped_degenerate,
                        r.dropped_non_finite, r.normals_generated, r.normals_renormalised, r.normals_replaced,
                        r.zero_uv_area_triangles, r.fallback_tangent_corners, r.duplicate_triangles})
    w.pod(n);
  w.pod(r.duplicates_dropped);
  w.pod(r.notices.size());
  for (const std::string& n : r.notices) w.text(n);
  auto texts = [&](const std::vector<std::string>& v) {
    w.pod(v.size());
    for (const std::string& t : v) w.text(t);
  };
  w.pod(m.layers.maps.size());
  for (const texture_ref& t : m.layers.maps) {
    w.text(t.name);
    w.text(t.file.string());
    w.pods(t.embedded);
    w.pod(t.raw.width);
    w.pod(t.raw.height);
    w.pod(t.raw.channels);
    w.pods(t.raw.data);
    w.text(t.slot);
    w.pod(t.scale);
    w.pod(t.uv_set);
    texts(t.materials);
  }
  texts(m.layers.flat_materials);
  return std::move(w.out);
}

imported_mesh deserialise(const std::string& bytes) {
  reader rd{bytes};
  imported_mesh m;
  m.model.vertices = rd.pods<vertex>();
  m.model.triangles = rd.pods<std::array<std::uint32_t, 3>>();
  m.model.layer = rd.pods<std::uint16_t>();
  import_report& r = m.report;
  for (std::string* t : {&r.file, &r.format, &r.normals, &r.uvs, &r.tangents}) *t = rd.text();
  for (std::size_t* n :
       {&r.meshes, &r.instances, &r.triangles, &r.dropped_points, &r.dropped_lines, &r.dropped_degenerate,
        &r.dropped_non_finite, &r.normals_generated, &r.normals_renormalised, &r.normals_replaced,
        &r.zero_uv_area_triangles, &r.fallback_tangent_corners, &r.duplicate_triangles})
    *n = rd.pod<std::size_t>();
  r.duplicates_dropped = rd.pod<bool>();
  for (std::size_t i = 0, n = rd.pod<std::size_t>(); i < n && rd.at < bytes.size(); ++i) r.notices.push_back(rd.text());
  auto texts = [&] {
    std::vector<std::string> v;
    for (std::size_t i = 0, n = rd.pod<std::size_t>(); i < n && rd.at < bytes.size(); ++i) v.push_back(rd.text());
    return v;
  };
  for (std::size_t i = 0, n = rd.pod<std::size_t>(); i < n && rd.at < bytes.size(); ++i) {
    texture_ref& t = m.layers.maps.emplace_back();
    t.name = rd.text();
    t.file = rd.text();
    t.embedded = rd.pods<std::uint8_t>();
    t.raw.width = rd.pod<int>();
    t.raw.height = rd.pod<int>();
    t.raw.channels = rd.pod<int>();
    t.raw.data = rd.pods<std::uint8_t>();
    t.slot = rd.text();
    t.scale = rd.pod<float>();
    t.uv_set = rd.pod<unsigned>();
    t.materials = texts();
  }
  m.layers.flat_materials = texts();
  return m;
}

// The importing child's limits. Address space: realistic assets of millions of triangles fit, a
// header that claims 10^11 vertices does not. CPU: a 100k-triangle OBJ takes 0.7 s. Wall clock:
// the CPU allowance with room for a loaded machine.
constexpr child_limits import_limits{std::size_t{3} << 30, 120, 300};

}  // namespace

imported_mesh from_scene(const aiScene& s, const std::string& name, const std::filesystem::path& dir,
                         const std::string& format, const import_options& options) {
  imported_mesh out;
  import_report& r = out.report;
  r.file = name;
  r.format = format;
  try {
    const std::vector<source_instance> inst = instances_of(s);
    r.instances = inst.size();
    std::vector<std::uint16_t> mesh_layer;
    std::vector<unsigned> uv_set;
    out.layers = layers_of(s, inst, dir, mesh_layer, uv_set);
    std::vector<source_mesh> meshes(s.mNumMeshes);
    std::vector<char> used(s.mNumMeshes, 0);
    for (const source_instance& in : inst) {
      if (used[in.mesh] || s.mMeshes[in.mesh] == nullptr) continue;
      used[in.mesh] = 1;
      meshes[in.mesh] = convert(*s.mMeshes[in.mesh], in.mesh, uv_set[in.mesh], r);
      meshes[in.mesh].layer = mesh_layer[in.mesh];
      ++r.meshes;
    }
    if (r.dropped_points + r.dropped_lines > 0)
      r.notices.push_back(std::to_string(r.dropped_points) + " point(s) and " + std::to_string(r.dropped_lines) +
                          " line(s) ignored (only triangles are rendered)");
    out.model = build_mesh(meshes, inst, options, r);
  } catch (const std::runtime_error& e) { throw std::runtime_error(name + ": " + e.what()); }
  if (r.dropped_degenerate > 0)
    r.notices.push_back(std::to_string(r.dropped_degenerate) + " zero-area triangle(s) dropped");
  if (r.dropped_non_finite > 0)
    r.notices.push_back(std::to_string(r.dropped_non_finite) +
                        " triangle(s) with a non-finite position (NaN or infinity) dropped");
  if (r.normals_generated > 0)
    r.notices.push_back("normals: " + std::to_string(r.normals_generated) + " vertex position(s) had none; " +
                        r.normals);
  if (r.normals_renormalised > 0)
    r.notices.push_back("normals: " + std::to_string(r.normals_renormalised) + " non-unit normal(s) renormalised");
  if (r.normals_replaced > 0)
    r.notices.push_back("normals: " + std::to_string(r.normals_replaced) +
                        " zero or NaN normal(s) replaced by the smooth normal");
  if (r.duplicate_triangles > 0)
    r.notices.push_back(
        std::to_string(r.duplicate_triangles) +
        " duplicated triangle(s) (the positions and winding of an earlier one) " +
        (r.duplicates_dropped
             ? "dropped (--duplicates drop)"
             : "kept (--duplicates keep): drawn twice, every blending GS pass applies twice and wraps"));
  if (r.uvs != "file") r.notices.push_back("UVs: none in the file; generated by " + r.uvs);
  if (r.zero_uv_area_triangles > 0)
    r.notices.push_back("tangents: " + std::to_string(r.zero_uv_area_triangles) +
                        " triangle(s) with zero UV area: their corners take a neighbouring triangle's frame, " +
                        std::to_string(r.fallback_tangent_corners) +
                        " corner(s) without one a fixed frame from the normal" +
                        (2 * r.zero_uv_area_triangles > r.triangles
                             ? "; most of the mesh samples the normal map at single points (are its UVs real?)"
                             : ""));
  return out;
}

imported_mesh import_mesh(const std::filesystem::path& file, const import_options& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw std::runtime_error(file.string() + ": cannot open the mesh");
  std::string bytes;
  try {
    bytes = run_in_child(
        [&] {
          Assimp::Importer imp;
          auto* io = new confined_io(file.parent_path());
          imp.SetIOHandler(io);  // owned by imp
          const aiScene* s = imp.ReadFile(file.string(), import_flags);
          if (const std::string& why = s == nullptr && io->refused().empty() ? io->probed() : io->refused();
              !why.empty())
            throw std::runtime_error("refers to " + why + "; only files in the mesh's folder or below it are read");
          std::string ext = file.extension().string();
          if (!ext.empty()) ext.erase(0, 1);
          return serialise(from_scene(scene_or_error(s, imp, file.string()), file.string(), file.parent_path(),
                                      format_of(s, ext), options));
        },
        import_limits);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what(), prefix = file.string() + ": ";
    throw std::runtime_error(what.compare(0, prefix.size(), prefix) == 0 ? what : prefix + what);
  }
  return deserialise(bytes);
}

imported_mesh import_mesh_from_memory(const std::string& bytes, const std::string& extension,
                                      const import_options& options) {
  const std::string name = "<memory>." + extension;
  std::string result;
  try {
    result = run_in_child(
        [&] {
          Assimp::Importer imp;
          const aiScene* s = imp.ReadFileFromMemory(bytes.data(), bytes.size(), import_flags, extension.c_str());
          return serialise(from_scene(scene_or_error(s, imp, name), name, {}, format_of(s, extension), options));
        },
        import_limits);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what(), prefix = name + ": ";
    throw std::runtime_error(what.compare(0, prefix.size(), prefix) == 0 ? what : prefix + what);
  }
  return deserialise(result);
}

}  // namespace gsdot3::pipeline
