// pipeline/mesh_export.cpp — the mesh as .glb through tinygltf (see mesh_export.hpp).
#include "pipeline/mesh_export.hpp"

#include <cstring>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <tiny_gltf.h>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline {

namespace {

// Appends `count` elements of `components` floats (or indices) to the buffer as one view and accessor.
template <class T>
int add_accessor(tinygltf::Model& g, const std::vector<T>& values, int type, int component_type, std::size_t count,
                 int target) {
  std::vector<unsigned char>& data = g.buffers[0].data;
  while (data.size() % 4 != 0) data.push_back(0);  // accessors are aligned to their component size
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  data.resize(data.size() + view.byteLength);
  std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  g.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = static_cast<int>(g.bufferViews.size()) - 1;
  a.componentType = component_type;
  a.count = count;
  a.type = type;
  g.accessors.push_back(a);
  return static_cast<int>(g.accessors.size()) - 1;
}

}  // namespace

void export_mesh_glb(const mesh& m, const std::filesystem::path& file) {
  std::vector<float> position, normal, tangent, uv;
  std::vector<double> lo(3, 0.0), hi(3, 0.0);
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const vertex& v = m.vertices[i];
    for (int k = 0; k < 3; ++k) {
      lo[static_cast<std::size_t>(k)] =
          i == 0 ? v.position[k] : std::min<double>(lo[static_cast<std::size_t>(k)], v.position[k]);
      hi[static_cast<std::size_t>(k)] =
          i == 0 ? v.position[k] : std::max<double>(hi[static_cast<std::size_t>(k)], v.position[k]);
    }
    position.insert(position.end(), {v.position.x, v.position.y, v.position.z});
    normal.insert(normal.end(), {v.normal.x, v.normal.y, v.normal.z});
    const float renderer_sign = glm::dot(glm::cross(v.normal, v.tangent), v.bitangent) < 0.0f ? -1.0f : 1.0f;
    tangent.insert(tangent.end(), {v.tangent.x, v.tangent.y, v.tangent.z, -renderer_sign});
    uv.insert(uv.end(), {v.uv.x, v.uv.y});
  }
  std::vector<std::uint32_t> indices;
  for (const auto& t : m.triangles) indices.insert(indices.end(), t.begin(), t.end());

  tinygltf::Model g;
  g.asset.version = "2.0";
  g.asset.generator = "gsdot3";
  g.buffers.resize(1);
  const std::size_t n = m.vertices.size();
  tinygltf::Primitive p;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  p.attributes["POSITION"] =
      add_accessor(g, position, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TARGET_ARRAY_BUFFER);
  g.accessors.back().minValues = lo;  // required for POSITION (glTF 2.0, "Accessors")
  g.accessors.back().maxValues = hi;
  p.attributes["NORMAL"] =
      add_accessor(g, normal, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TARGET_ARRAY_BUFFER);
  p.attributes["TANGENT"] =
      add_accessor(g, tangent, TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TARGET_ARRAY_BUFFER);
  p.attributes["TEXCOORD_0"] =
      add_accessor(g, uv, TINYGLTF_TYPE_VEC2, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TARGET_ARRAY_BUFFER);
  p.indices = add_accessor(g, indices, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size(),
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  g.meshes.resize(1);
  g.meshes[0].name = "gsdot3";
  g.meshes[0].primitives.push_back(p);
  g.nodes.resize(1);
  g.nodes[0].mesh = 0;
  g.scenes.resize(1);
  g.scenes[0].nodes.push_back(0);
  g.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&g, out, false, true))
    throw std::runtime_error(file.string() + ": cannot write the glTF file");
  write_file_atomically(file, out.str());
}

}  // namespace gsdot3::pipeline
