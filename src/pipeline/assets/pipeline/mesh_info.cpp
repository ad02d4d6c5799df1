// pipeline/mesh_info.cpp — mesh-info's figures and output (see mesh_info.hpp).
#include "pipeline/mesh_info.hpp"

#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/input_report.hpp"

namespace gsdot3::pipeline {

mesh_figures measure(const mesh& m) {
  mesh_figures f;
  f.vertices = m.vertices.size();
  f.triangles = m.triangles.size();
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const vertex& v = m.vertices[i];
    f.lo = i == 0 ? v.position : glm::min(f.lo, v.position);
    f.hi = i == 0 ? v.position : glm::max(f.hi, v.position);
    // The renderer's sign is +1 where b = n × t; glTF's w is its negation (mesh_export.hpp).
    ++(glm::dot(glm::cross(v.normal, v.tangent), v.bitangent) < 0.0f ? f.w_plus : f.w_minus);
  }
  for (const auto& t : m.triangles) {
    const glm::vec2 a = m.vertices[t[0]].uv, b = m.vertices[t[1]].uv, c = m.vertices[t[2]].uv;
    f.uv_area += 0.5 * std::fabs(static_cast<double>((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
  }
  return f;
}

namespace {

// The materials' normal maps, one a layer (mesh_import.hpp's material_layers).
nlohmann::json normal_maps_json(const imported_mesh& im) {
  nlohmann::json maps = nlohmann::json::array();
  for (const texture_ref& t : im.layers.maps)
    maps.push_back({{"name", t.name},
                    {"slot", t.slot},
                    {"embedded", t.file.empty()},
                    {"file", t.file.empty() ? "" : t.file.string()},
                    {"scale", t.scale},
                    {"uv_set", t.uv_set},
                    {"materials", t.materials}});
  return maps;
}

std::string xyz(glm::vec3 v) {
  std::ostringstream o;
  o << v.x << "," << v.y << "," << v.z;
  return o.str();
}

}  // namespace

std::string mesh_info_json(const imported_mesh& im, const mesh_figures& f) {
  nlohmann::json j = nlohmann::json::parse(mesh_json(im.report));
  j["vertices"] = f.vertices;
  j["bounds"] = {{"min", {f.lo.x, f.lo.y, f.lo.z}}, {"max", {f.hi.x, f.hi.y, f.hi.z}}};
  j["uvs"] = {{"source", im.report.uvs}, {"area", f.uv_area}};
  j["tangents"]["w"] = {{"plus", f.w_plus}, {"minus", f.w_minus}};
  j["normal_maps"] = normal_maps_json(im);
  j["materials_without_normal_map"] = im.layers.flat_materials;
  j["notices"] = im.report.notices;
  return j.dump();
}

std::string mesh_info_text(const imported_mesh& im, const mesh_figures& f) {
  const import_report& r = im.report;
  std::ostringstream o;
  o << "file        " << r.file << " (" << r.format << ")\n"
    << "read        " << r.meshes << " mesh(es), " << r.instances << " instance(s)\n"
    << "drawn       " << f.triangles << " triangles, " << f.vertices << " vertices\n"
    << "dropped     " << r.dropped_points << " point(s), " << r.dropped_lines << " line(s), " << r.dropped_degenerate
    << " zero-area triangle(s), " << r.dropped_non_finite << " with a non-finite position\n"
    << "duplicates  " << r.duplicate_triangles << " triangle(s) with the positions and winding of an earlier one, "
    << (r.duplicates_dropped ? "dropped" : "kept") << "\n"
    << "bounds      min " << xyz(f.lo) << "  max " << xyz(f.hi) << "\n"
    << "normals     " << r.normals << "; positions generated " << r.normals_generated << ", renormalised "
    << r.normals_renormalised << ", replaced " << r.normals_replaced << "\n"
    << "UVs         " << r.uvs << "; area " << f.uv_area << " (repeats of the map), " << r.zero_uv_area_triangles
    << " triangle(s) with zero UV area\n"
    << "tangents    " << r.tangents << "; w +1 on " << f.w_plus << " vertices, -1 (mirrored UVs) on " << f.w_minus
    << ", " << r.fallback_tangent_corners << " fallback corner(s)\n";
  for (std::size_t k = 0; k < im.layers.maps.size(); ++k) {
    const texture_ref& t = im.layers.maps[k];
    o << "layer " << k << "     " << t.name << " (" << t.slot << ", "
      << (t.file.empty() ? "embedded" : t.file.string());
    if (t.scale != 1.0f) o << ", scale " << t.scale;
    if (t.uv_set != 0) o << ", UV set " << t.uv_set;
    o << "); materials:";
    for (const std::string& m : t.materials) o << " " << m;
    o << "\n";
  }
  if (im.layers.maps.empty()) {
    o << "normal map  none in the materials\n";
  } else if (!im.layers.flat_materials.empty()) {
    o << "layer " << im.layers.maps.size() << "     flat (no normal map); materials:";
    for (const std::string& m : im.layers.flat_materials) o << " " << m;
    o << "\n";
  }
  for (const std::string& n : r.notices) o << "notice      " << n << "\n";
  return o.str();
}

}  // namespace gsdot3::pipeline
