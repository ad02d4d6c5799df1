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

// A material's normal map at the sides `base` names (0: its own); nullopt (with a notice) when its file
// is not there.
std::optional<loaded_normal_map> material_normal_map(const texture_ref& t, const normal_map_settings& base, float bump,
                                                     const std::string& mesh_file, std::string& source,
                                                     const std::function<void(const std::string&)>& say) {
  normal_map_settings s = base;
  s.grey_is_height = t.slot == "bump";  // an MTL bump map may be a height map (grey) or a normal map
  s.height_strength = bump;
  s.xy_scale = t.scale;
  if (!t.embedded.empty()) {
    source = "material " + t.slot + " texture '" + t.name + "' (embedded)";
    return load_normal_map(t.embedded.data(), t.embedded.size(), mesh_file + ": embedded texture '" + t.name + "'", s);
  }
  if (t.raw.width > 0) {
    source = "material " + t.slot + " texture '" + t.name + "' (embedded texels)";
    loaded_normal_map m = normal_map_from_image(t.raw, mesh_file + ": embedded texture '" + t.name + "'", s);
    m.format = "texels";
    return m;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(t.file, ec)) {
    say("normal map: the material names '" + t.name + "', which is not at " + t.file.string() + "; that layer is flat");
    return std::nullopt;
  }
  source = "material " + t.slot + " texture " + t.file.string();
  return load_normal_map(t.file, s);
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& x : v) out += (out.empty() ? "" : ", ") + x;
  return out;
}

// A flat layer: every texel (0, 0, 1).
normal_map flat_map(int w, int h) {
  normal_map m;
  m.width = w, m.height = h;
  m.palette = {glm::vec3(0, 0, 1)};
  m.index.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  m.unquantised.assign(m.index.size(), glm::vec3(0, 0, 1));
  return m;
}

// The materials' maps as the layers of one normal map (scene.hpp): each loaded, then every one at the
// largest width and height among them (the GS methods' UVs are in texels of one size), a layer per
// map, the flat layer last; one line each into sum.layers. The first loaded map stands for them in
// sum.normal_map (nullopt: none could be loaded, every layer flat at 8×8).
std::optional<loaded_normal_map> material_maps(const material_layers& ml, const scene_request& r, normal_map& out,
                                               input_summary& sum, const std::function<void(const std::string&)>& say) {
  const std::string& file = sum.mesh->file;
  std::vector<std::optional<loaded_normal_map>> loaded;
  std::vector<std::string> sources(ml.maps.size());
  int W = 8, H = 8;
  for (std::size_t k = 0; k < ml.maps.size(); ++k) {
    loaded.push_back(material_normal_map(ml.maps[k], r.normal_maps, r.bump, file, sources[k], say));
    if (loaded.back()) W = std::max(W, loaded.back()->map.width), H = std::max(H, loaded.back()->map.height);
  }
  normal_map_settings common = r.normal_maps;
  common.width = W, common.height = H;
  std::vector<normal_map> layers;
  std::optional<loaded_normal_map> first;
  for (std::size_t k = 0; k < ml.maps.size(); ++k) {
    std::optional<loaded_normal_map>& m = loaded[k];
    const texture_ref& t = ml.maps[k];
    if (m && (m->map.width != W || m->map.height != H))
      m = material_normal_map(t, common, r.bump, file, sources[k], [](const std::string&) {});
    layers.push_back(m ? m->map : flat_map(W, H));
    std::string line = m ? sources[k] + " (" + m->format + " " + std::to_string(m->source_width) + "×" +
                               std::to_string(m->source_height) + " at " + std::to_string(W) + "×" + std::to_string(H) +
                               ")"
                         : "flat: '" + t.name + "' not found";
    if (t.scale != 1.0f) line += ", scale " + degrees(t.scale);
    if (t.uv_set != 0) line += ", UV set " + std::to_string(t.uv_set);
    sum.layers.push_back(line + "; materials: " + joined(t.materials));
    if (m && !first) first = m, sum.normal_map_source = sources[k];
  }
  if (!ml.flat_materials.empty()) {
    layers.push_back(flat_map(W, H));
    sum.layers.push_back("flat (no normal map); materials: " + joined(ml.flat_materials));
  }
  out = stacked(layers);
  if (layers.size() > 1)
    sum.normal_map_source = "the materials' " + std::to_string(ml.maps.size()) + " normal map(s)" +
                            (ml.flat_materials.empty() ? "" : " and a flat layer") + ", one layer each";
  return first;
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
  material_layers materials;
  if (!r.mesh.empty()) {
    imported_mesh im = import_mesh(r.mesh, r.import);
    sum.mesh = im.report;
    for (const std::string& n : im.report.notices) say(n);
    s.model = std::move(im.model);
    materials = std::move(im.layers);
    in.description = "mesh " + r.mesh.string() + " (" + std::to_string(s.model.triangles.size()) + " triangles)";
  }

  std::optional<loaded_normal_map> nm;
  const bool own_map = !r.height_map.empty() || !r.normal_map.empty();
  if (own_map) s.model.layer.clear();  // the one map given, on every triangle
  if (!r.height_map.empty()) {
    s.normals = load_height_map_png(r.height_map, r.bump);
    sum.normal_map_source = "--height-map " + r.height_map.string();
    in.description += ", height map " + r.height_map.string();
  } else if (!r.normal_map.empty()) {
    nm = load_normal_map(r.normal_map, r.normal_maps);
    sum.normal_map_source = "--normal-map " + r.normal_map.string();
    in.description += ", normal map " + r.normal_map.string();
  } else if (materials.count() > 0) {
    nm = material_maps(materials, r, s.normals, sum, say);
    in.description += materials.count() > 1
                          ? ", its materials' normal maps (" + std::to_string(materials.count()) + " layers)"
                      : nm ? ", its material's normal map"
                           : "";
  }
  if (nm) {
    if (nm->resampled)
      say("normal map: " + size_text(nm->source_width, nm->source_height) + " resampled to " +
          size_text(nm->map.width, nm->map.height) + " (GS textures have power-of-two sides up to 1024), filter " +
          resample_filter);
    if (nm->from_height)
      say("normal map: the bump texture is grey, read as a height map (slope " + degrees(r.bump) + " per grey level)");
    if (own_map) s.normals = nm->map;  // the materials' layers are in s.normals already
    sum.normal_map = std::move(nm);
  }
  if (own_map || materials.count() > 0) s.diffuse = procedural_diffuse(s.normals.width, s.normals.height);

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
