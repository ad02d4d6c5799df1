// pipeline/input_report.cpp — the "input" object and section (see input_report.hpp).
#include "pipeline/input_report.hpp"

#include <nlohmann/json.hpp>

namespace gsdot3::pipeline {

namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string mesh_json(const import_report& r) {
  const nlohmann::json j = {
      {"file", r.file},
      {"format", r.format},
      {"meshes", r.meshes},
      {"instances", r.instances},
      {"triangles", r.triangles},
      {"dropped",
       {{"points", r.dropped_points},
        {"lines", r.dropped_lines},
        {"zero_area_triangles", r.dropped_degenerate},
        {"non_finite_triangles", r.dropped_non_finite}}},
      {"duplicate_triangles", {{"found", r.duplicate_triangles}, {"action", r.duplicates_dropped ? "drop" : "keep"}}},
      {"normals",
       {{"source", r.normals},
        {"generated_positions", r.normals_generated},
        {"renormalised_positions", r.normals_renormalised},
        {"replaced_positions", r.normals_replaced}}},
      {"uvs", r.uvs},
      {"tangents",
       {{"source", r.tangents},
        {"convention", "MikkTSpace (glTF 2.0)"},
        {"zero_uv_area_triangles", r.zero_uv_area_triangles},
        {"fallback_corners", r.fallback_tangent_corners}}}};
  return j.dump();
}

std::string input_json(const input_summary& s) {
  nlohmann::json j;
  if (s.mesh) {
    j["mesh"] = nlohmann::json::parse(mesh_json(*s.mesh));
  } else {
    j["mesh"] = {{"file", nullptr}, {"format", "embedded procedural head"}};
  }
  j["normal_map"] = {{"source", s.normal_map_source}};
  if (s.normal_map) {
    j["normal_map"]["green"] = s.normal_map_y;
    const loaded_normal_map& n = *s.normal_map;
    j["normal_map"]["format"] = n.format;
    j["normal_map"]["source_size"] = {n.source_width, n.source_height};
    j["normal_map"]["size"] = {n.map.width, n.map.height};
    j["normal_map"]["resampled"] = n.resampled;
    if (n.resampled) j["normal_map"]["filter"] = resample_filter;
    j["normal_map"]["from_height_map"] = n.from_height;
  }
  if (!s.layers.empty()) j["normal_map"]["layers"] = s.layers;
  j["camera"] = s.camera;
  j["lights"] = s.lights;
  j["notices"] = s.notices;
  return j.dump();
}

std::string input_html(const input_summary& s) {
  auto row = [](const std::string& k, const std::string& v) {
    return "<tr><th>" + k + "</th><td style=\"text-align:left\">" + escape(v) + "</td></tr>\n";
  };
  std::string h = "<h2>Input</h2>\n<table>\n";
  if (s.mesh) {
    const import_report& r = *s.mesh;
    h += row("mesh", r.file + " (" + r.format + "): " + std::to_string(r.meshes) + " mesh(es), " +
                         std::to_string(r.triangles) + " triangles");
    h += row("normals", r.normals);
    h += row("UVs", r.uvs);
    h += row("tangents", r.tangents);
  } else {
    h += row("mesh", "embedded procedural head");
  }
  std::string nm = s.normal_map_source;
  if (s.normal_map)
    nm += " (" + s.normal_map->format + " " + std::to_string(s.normal_map->source_width) + "×" +
          std::to_string(s.normal_map->source_height) +
          (s.normal_map->resampled ? ", resampled to " + std::to_string(s.normal_map->map.width) + "×" +
                                         std::to_string(s.normal_map->map.height)
                                   : "") +
          ", green " + s.normal_map_y + ")";
  h += row("normal map", nm);
  for (std::size_t k = 0; k < s.layers.size(); ++k) h += row("layer " + std::to_string(k), s.layers[k]);
  h += row("camera", s.camera);
  h += row("lights", s.lights);
  for (const std::string& n : s.notices) h += row("notice", n);
  return h + "</table>\n";
}

}  // namespace gsdot3::pipeline
