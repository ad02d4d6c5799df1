// pipeline/scene_input.cpp — user input to a scene (see scene_input.hpp).
#include "pipeline/scene_input.hpp"

#include <cstdio>
#include <stdexcept>

#include "pipeline/default_scene.hpp"
#include "pipeline/files.hpp"
#include "pipeline/floor.hpp"
#include "pipeline/framing.hpp"

namespace gsdot3::pipeline {

namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

std::string degrees(float v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", static_cast<double>(v));
  return b;
}

// The material's normal map; nullopt (with a notice) when its file is not there.
std::optional<loaded_normal_map> material_normal_map(const texture_ref& t, const normal_map_settings& base, float bump,
                                                     input_summary& sum,
                                                     const std::function<void(const std::string&)>& say) {
  normal_map_settings s = base;
  s.grey_is_height = t.slot == "bump";  // an MTL bump map may be a height map (grey) or a normal map
  s.height_strength = bump;
  if (!t.embedded.empty()) {
    sum.normal_map_source = "material " + t.slot + " texture '" + t.name + "' (embedded)";
    return load_normal_map(t.embedded.data(), t.embedded.size(), sum.mesh->file + ": embedded texture '" + t.name + "'",
                           s);
  }
  if (t.raw.width > 0) {
    sum.normal_map_source = "material " + t.slot + " texture '" + t.name + "' (embedded texels)";
    loaded_normal_map m = normal_map_from_image(t.raw, sum.mesh->file + ": embedded texture '" + t.name + "'", s);
    m.format = "texels";
    return m;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(t.file, ec)) {
    say("normal map: the material names '" + t.name + "', which is not at " + t.file.string() +
        "; the procedural map is used");
    return std::nullopt;
  }
  sum.normal_map_source = "material " + t.slot + " texture " + t.file.string();
  return load_normal_map(t.file, s);
}

}  // namespace

scene_input make_scene(const scene_request& r, const std::function<void(const std::string&)>& notice) {
  scene_input in;
  input_summary& sum = in.summary;
  auto say = [&](const std::string& m) {
    sum.notices.push_back(m);
    notice(m);
  };
  sum.normal_map_y = r.normal_maps.y == normal_map_y::up ? "up" : "down";
  scene& s = in.s;
  s = default_scene();
  in.description = "embedded procedural head (" + std::to_string(s.model.triangles.size()) + " triangles)";
  std::optional<texture_ref> material_map;
  if (!r.mesh.empty()) {
    imported_mesh im = import_mesh(r.mesh, r.import);
    sum.mesh = im.report;
    for (const std::string& n : im.report.notices) say(n);
    s.model = std::move(im.model);
    material_map = im.normal_texture;
    in.description = "mesh " + r.mesh.string() + " (" + std::to_string(s.model.triangles.size()) + " triangles)";
  }

  std::optional<loaded_normal_map> nm;
  if (!r.height_map.empty()) {
    s.normals = load_height_map_png(r.height_map, r.bump);
    sum.normal_map_source = "--height-map " + r.height_map.string();
    in.description += ", height map " + r.height_map.string();
  } else if (!r.normal_map.empty()) {
    nm = load_normal_map(r.normal_map, r.normal_maps);
    sum.normal_map_source = "--normal-map " + r.normal_map.string();
    in.description += ", normal map " + r.normal_map.string();
  } else if (material_map) {
    if (material_map->other_maps > 0)
      say("normal map: " + std::to_string(material_map->other_maps) +
          " other material(s) name other normal maps; only '" + material_map->name +
          "' is used (the renderer has one normal map)");
    nm = material_normal_map(*material_map, r.normal_maps, r.bump, sum, say);
    if (nm) in.description += ", its material's normal map";
  }
  if (nm) {
    if (nm->resampled)
      say("normal map: " + size_text(nm->source_width, nm->source_height) + " resampled to " +
          size_text(nm->map.width, nm->map.height) + " (GS textures have power-of-two sides up to 1024), filter " +
          resample_filter);
    if (nm->from_height)
      say("normal map: the bump texture is grey, read as a height map (slope " + degrees(r.bump) + " per grey level)");
    s.normals = nm->map;
    sum.normal_map = std::move(nm);
  }
  if (!r.height_map.empty() || sum.normal_map) s.diffuse = procedural_diffuse(s.normals.width, s.normals.height);

  s.width = r.width;
  s.height = r.height;
  std::array<float, 2> view = r.view.value_or(std::array<float, 2>{0.0f, 0.0f});
  const bool framed = !r.mesh.empty() || r.view;
  if (framed) {
    const bounding_sphere b = bounds_of(s.model);
    normalise(s.model, b);
    say("the model is centred and scaled to its unit bounding sphere (centre " + degrees(b.centre.x) + "," +
        degrees(b.centre.y) + "," + degrees(b.centre.z) + ", radius " + degrees(b.radius) +
        "): --camera and --light positions are in that frame");
  }
  // The default view of a mesh sees its faces' fronts, or it is turned to where it does.
  if (!r.mesh.empty() && !r.view && !r.eye)
    if (const std::optional<front_view> v = view_of_fronts(s.model, r.width, r.height, s.view.fov_y_degrees);
        v && (v->azimuth != view[0] || v->elevation != view[1])) {
      say("framing: no triangle faces the default view (azimuth 0, elevation 0: they face away or are edge-on); "
          "viewed from azimuth " +
          degrees(v->azimuth) + ", elevation " + degrees(v->elevation) + " instead, where " +
          std::to_string(v->facing) + " of " + std::to_string(s.model.triangles.size()) +
          " face the camera (--view chooses)");
      view = {v->azimuth, v->elevation};
    }
  if (r.eye) {
    s.view.eye = *r.eye;
    sum.camera =
        "--camera " + degrees(r.eye->x) + "," + degrees(r.eye->y) + "," + degrees(r.eye->z) + " looking at the origin";
  } else if (framed) {
    s.view = frame_unit_sphere(view[0], view[1], r.width, r.height, s.view.fov_y_degrees);
    sum.camera = "framed: the unit bounding sphere fills the frame with a 10% margin, azimuth " + degrees(view[0]) +
                 ", elevation " + degrees(view[1]);
  }
  if (!r.lights.empty()) {
    s.lights = r.lights;
    sum.lights = "--light (" + std::to_string(r.lights.size()) + ")";
  } else if (framed) {
    s.lights = default_lights(view[0], view[1]);
    sum.lights = "the embedded scene's two, relative to the unit bounding sphere, turned with the view";
  }
  if (r.floor) {
    s.plain = floor_under(s.model);
    in.description += "; step 5: a Gouraud-shaded floor (" + std::to_string(s.plain.triangles.size()) +
                      " triangles, not normal-mapped) drawn after step 4 into the same buffer";
  }
  return in;
}

}  // namespace gsdot3::pipeline
