// gsdot3 render's options (render_args.hpp): parsed into the scene, the render options and the
// methods; the frame limits checked once (pipeline/frame_limits.hpp).
#include "render_args.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/mesh_import.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/scene_input.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::cli {
namespace {

std::vector<float> parse_floats(const std::string& what, const std::string& text, std::size_t n) {
  std::vector<float> v;
  std::stringstream in(text);
  for (std::string tok; std::getline(in, tok, ',');) {
    std::size_t used = 0;
    float f = 0;
    try {
      f = std::stof(tok, &used);
    } catch (const std::exception&) { used = 0; }
    if (used != tok.size() || tok.empty() || !std::isfinite(f))
      throw usage_error(what + ": '" + tok + "' is not a finite number (in '" + text + "')");
    v.push_back(f);
  }
  if (v.size() != n)
    throw usage_error(what + ": expected " + std::to_string(n) + " comma-separated numbers, got '" + text + "'");
  return v;
}

// [point:|directional:]X,Y,Z:RRGGBB — a point light's world position, or the world direction towards a
// directional light (nonzero), and the colour in hex (0x80 per channel = 1.0); or
// spot:X,Y,Z:DX,DY,DZ:DEGREES:RRGGBB — a spot light's position, the cone's axis (nonzero) and its
// half-angle (1..80 degrees).
pipeline::scene_light parse_light(std::string text) {
  pipeline::scene_light l;
  for (const auto& [prefix, k] : {std::pair{std::string("point:"), pipeline::light_kind::point},
                                  std::pair{std::string("directional:"), pipeline::light_kind::directional},
                                  std::pair{std::string("spot:"), pipeline::light_kind::spot}})
    if (text.starts_with(prefix)) {
      l.kind = k;
      text.erase(0, prefix.size());
    }
  const bool spot = l.kind == pipeline::light_kind::spot;
  std::vector<std::string> fields;
  for (std::size_t at = 0;;) {
    const auto colon = text.find(':', at);
    fields.push_back(text.substr(at, colon == std::string::npos ? std::string::npos : colon - at));
    if (colon == std::string::npos) break;
    at = colon + 1;
  }
  if (fields.size() != (spot ? 4u : 2u))
    throw usage_error(spot ? "--light: expected spot:X,Y,Z:DX,DY,DZ:DEGREES:RRGGBB, got 'spot:" + text + "'"
                           : "--light: expected [point:|directional:]X,Y,Z:RRGGBB, got '" + text + "'");
  const auto p = parse_floats("--light", fields[0], 3);
  l.position = {p[0], p[1], p[2]};
  const std::string& hex = fields.back();
  if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw usage_error("--light: colour must be 6 hex digits RRGGBB, got '" + hex + "'");
  if (l.kind == pipeline::light_kind::directional && p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f)
    throw usage_error("--light: a directional light needs a nonzero direction, got '" + text + "'");
  if (spot) {
    const auto d = parse_floats("--light", fields[1], 3);
    if (d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f)
      throw usage_error("--light: a spot light needs a nonzero axis, got '" + fields[1] + "'");
    l.direction = {d[0], d[1], d[2]};
    l.cone_degrees = parse_floats("--light", fields[2], 1)[0];
    if (!(l.cone_degrees >= 1.0f && l.cone_degrees <= 80.0f))
      throw usage_error("--light: a spot light's half-angle must be 1..80 degrees, got '" + fields[2] + "'");
  }
  const unsigned long c = std::stoul(hex, nullptr, 16);
  l.colour = {static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8), static_cast<std::uint8_t>(c)};
  return l;
}

std::pair<int, int> parse_size(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 16 || h < 16 || w > 2048 || h > 2048)
    throw usage_error("--size: expected WxH with 16..2048 each (e.g. 512x448), got '" + text + "'");
  return {w, h};
}

// A comma-separated list of method names: the GS methods, the other seeds' scheme methods
// (pipeline::scheme_methods()), "gs" (every GS method) or "all" (every method).
struct method_choice {
  std::vector<pipeline::method> gs;
  std::vector<const pipeline::scheme_method*> schemes;
};
method_choice parse_methods(const std::string& list) {
  method_choice c;
  auto add_gs = [&](pipeline::method m) {
    if (std::find(c.gs.begin(), c.gs.end(), m) == c.gs.end()) c.gs.push_back(m);
  };
  auto add_scheme = [&](const pipeline::scheme_method* m) {
    if (std::find(c.schemes.begin(), c.schemes.end(), m) == c.schemes.end()) c.schemes.push_back(m);
  };
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (name == "all" || name == "gs") {
      for (auto m : pipeline::gs_methods) add_gs(m);
      if (name == "all")
        for (const auto& sm : pipeline::scheme_methods()) add_scheme(&sm);
      continue;
    }
    if (const auto gm = pipeline::find_method(name)) {
      add_gs(*gm);
    } else if (const auto* sm = pipeline::find_scheme_method(name)) {
      add_scheme(sm);
    } else {
      std::string known = pipeline::method_names();
      for (const auto& m : pipeline::scheme_methods()) known += ", " + std::string(m.name);
      throw usage_error("--method: unknown method '" + name + "' (expected a comma-separated list of " + known +
                        ", gs or all)");
    }
  }
  // The float reference and the schemes take the visible triangle per pixel from a GS render.
  if (c.gs.empty())
    throw usage_error("--method: name at least one GS method (" + pipeline::method_names() +
                      "): the others are drawn on its geometry");
  return c;
}

}  // namespace

void progress(const std::string& m) { std::cerr << "gsdot3: " << m << "\n"; }

// The scene, the render options and the methods of render's options (everything but --out).
scene_setup setup(const render_args& a, pipeline::frame_use use) {
  scene_setup req;
  const method_choice chosen = parse_methods(a.method);
  req.methods = chosen.gs;
  req.schemes = chosen.schemes;
  if (a.s < 1 || a.s > 127)
    throw usage_error("--s: the tolight scale must be 1..127 (it is packed as a signed char), got " +
                      std::to_string(a.s));
  req.options.s = a.s;
  if (a.filter != "nearest" && a.filter != "bilinear")
    throw usage_error("--filter: expected nearest or bilinear, got '" + a.filter + "'");
  req.options.bilinear = a.filter == "bilinear";
  if (a.path != "cached" && a.path != "reference")
    throw usage_error("--path: expected cached or reference, got '" + a.path + "'");
  req.options.path = a.path == "cached" ? pipeline::raster_path::cached : pipeline::raster_path::reference;
  if (a.threads < 1 || a.threads > 64) throw usage_error("--threads: expected 1..64");
  req.options.threads = a.threads;
  if (a.specular) {
    if (!(*a.specular >= 1.0 && *a.specular <= 256.0)) throw usage_error("--specular: the ILP power must be 1..256");
    req.options.specular = true;
    req.options.specular_power = *a.specular;
  }
  req.options.model = a.model.resolve();
  const auto [w, h] = parse_size(a.size);
  req.options.memory_path = a.memory_path;
  req.options.simd = !a.scalar;
  if (a.dpb_clear == "z-trick")
    req.options.dpb_clear = pipeline::dpb_clear_mode::z_trick;
  else if (a.dpb_clear == "z-trick-psmz32")
    req.options.dpb_clear = pipeline::dpb_clear_mode::z_trick_psmz32;
  else if (a.dpb_clear != "explicit")
    throw usage_error("--dpb-clear: expected explicit, z-trick or z-trick-psmz32, got '" + a.dpb_clear + "'");
  req.options.buffers = a.draw_buffers == 1 ? pipeline::draw_buffers::one : pipeline::draw_buffers::two;
  std::vector<pipeline::scene_light> lights;
  for (const std::string& l : a.lights) lights.push_back(parse_light(l));
  const bool spot = std::any_of(lights.begin(), lights.end(),
                                [](const pipeline::scene_light& l) { return l.kind == pipeline::light_kind::spot; });
  if (spot && !req.schemes.empty())
    throw usage_error("--light spot:...: the other seeds' methods draw no spot light (section 3.6 is the GS's)");
  req.options.spot_after_first_pass = a.spot_after_first_pass;
  if (a.lod_share && !a.lod_distance.empty())
    throw usage_error("--lod-fade and --lod-distance exclude each other (one gives the share, the other derives it)");
  std::optional<std::array<double, 2>> lod_range;
  if (!a.lod_distance.empty()) {
    const auto r = parse_floats("--lod-distance", a.lod_distance, 2);
    if (!(r[0] >= 0.0f && r[0] < r[1]))
      throw usage_error("--lod-distance: expected NEAR,FAR with 0 <= NEAR < FAR, got '" + a.lod_distance + "'");
    lod_range = std::array<double, 2>{r[0], r[1]};
  }
  std::vector<float> eye;
  if (!a.camera.empty()) eye = parse_floats("--camera", a.camera, 3);
  // The frame limits (pipeline/frame_limits.hpp, the renderer's and the dump's own check): first on
  // what the options and lights already say, so that they fail at once, then on the built scene.
  auto check_limits = [&](const pipeline::scene& s) {
    for (const pipeline::method m : req.methods)
      if (const std::optional<std::string> why = pipeline::broken_limit(s, m, req.options, use))
        throw usage_error(*why);
  };
  pipeline::scene outline;
  outline.width = w, outline.height = h;
  outline.lights = a.lod_share ? pipeline::split_for_lod(lights, *a.lod_share) : lights;
  check_limits(outline);

  const pipeline::import_options import = parse_import_options(a.import);

  if (!a.normal_map.empty() && !a.height_map.empty())
    throw usage_error("--normal-map and --height-map exclude each other");
  if (!a.height_map.empty() && !(a.bump > 0.0f && a.bump <= 100.0f))
    throw usage_error("--bump: expected a strength in (0, 100]");
  if (a.normal_map_y != "up" && a.normal_map_y != "down")
    throw usage_error("--normal-map-y: expected up or down, got '" + a.normal_map_y + "'");
  pipeline::scene_request sr;
  sr.mesh = a.mesh;
  sr.normal_map = a.normal_map;
  sr.height_map = a.height_map;
  sr.bump = a.bump;
  sr.import = import;
  sr.normal_maps.y = a.normal_map_y == "up" ? pipeline::normal_map_y::up : pipeline::normal_map_y::down;
  if (!a.view.empty()) {
    const auto v = parse_floats("--view", a.view, 2);
    sr.view = std::array<float, 2>{v[0], v[1]};
  }
  if (!eye.empty()) sr.eye = glm::vec3(eye[0], eye[1], eye[2]);
  sr.lights = lights;
  sr.floor = a.floor;
  sr.width = w;
  sr.height = h;
  progress("building the scene");
  try {
    req.in = pipeline::make_scene(sr, progress);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
  std::optional<double> share = a.lod_share;
  if (lod_range) {
    const double d = pipeline::camera_distance(req.in.s);
    share = pipeline::lod_share_at(d, (*lod_range)[0], (*lod_range)[1]);
    char text[200];
    std::snprintf(text, sizeof text,
                  "; section 3.8's level of detail: the camera %.4g from the model's centre, per-pixel share %.6g "
                  "(1 at %.4g, 0 at %.4g, linear between)",
                  d, *share, (*lod_range)[0], (*lod_range)[1]);
    req.in.description += text;
    progress(text + 2);
  }
  if (share) req.in.s.lights = pipeline::split_for_lod(req.in.s.lights, *share);
  if (a.normal_map_bits != 8)  // the maps read are 8-bit
    req.in.s.normals = pipeline::with_index_bits(req.in.s.normals, a.normal_map_bits);
  if (a.normal_map_bits == 4)
    req.in.description += "; 4-bit normal map (PSMT4, 16 palette entries quantised from the 8-bit map)";
  if (a.normal_map_bits == 24)
    req.in.description +=
        "; 24-bit normal map: four-pass samples three 8-bit component maps (section 3.6), the float reference the "
        "unquantised normals; two-pass, three-pass, the 2002 method and the other seeds' methods read the 8-bit "
        "palettised map";
  check_limits(req.in.s);
  return req;
}

void add_options(CLI::App* cmd, render_args& a) {
  std::string methods = "comma-separated: " + pipeline::method_names();
  for (const auto& m : pipeline::scheme_methods()) methods += ", " + std::string(m.name);
  cmd->add_option("--method", a.method, methods + "; gs = the GS methods, all = every method")->capture_default_str();
  cmd->add_option(
      "--mesh", a.mesh,
      "mesh file read by assimp: OBJ, glTF 2.0 (.gltf, .glb), PLY, FBX, Collada, ...; all its meshes merged with "
      "their node transforms; default: the embedded head");
  add_import_options(cmd, a.import);
  cmd->add_option(
      "--normal-map", a.normal_map,
      "tangent-space normal map, PNG, JPEG or TGA of any size (resampled to power-of-two sides 8..1024), quantised "
      "to 256 entries; default: the mesh material's (glTF normalTexture, MTL norm/bump), else the procedural one");
  cmd->add_option("--normal-map-y", a.normal_map_y,
                  "the normal map's green channel points up (OpenGL, glTF) | down (DirectX) the image")
      ->capture_default_str();
  cmd->add_option(
      "--height-map", a.height_map,
      "8-bit grey PNG height map (power-of-two sides) turned into the normal map (instead of --normal-map)");
  cmd->add_option("--bump", a.bump, "height-map slope scale (per grey level)")->capture_default_str();
  cmd->add_option(
      "--light", a.lights,
      "light [point:]X,Y,Z:RRGGBB (point light at a world position), directional:X,Y,Z:RRGGBB (world "
      "direction towards the light; section 3: the same tolight at every vertex) or spot:X,Y,Z:DX,DY,DZ:DEG:RRGGBB "
      "(section 3.6: a point light at X,Y,Z through a projective intensity texture, a cone of half-angle DEG about "
      "the axis DX,DY,DZ; four-pass blends it over the DPB after its four passes, the other GS methods over the "
      "post filter's sum); colour in hex, 0x80 = 1.0; "
      "repeat for more lights; "
      "default: green 109820 at -2.2,1.4,2.2 and blue 1038B0 at 2.6,-0.2,0.4 (for a framed mesh: turned with --view)");
  cmd->add_option(
      "--camera", a.camera,
      "camera position X,Y,Z looking at the origin (default: embedded scene 0,0.15,3.6; a mesh is framed, and "
      "centred and scaled to its unit bounding sphere, so X,Y,Z are in units of its radius from its centre)");
  cmd->add_option(
      "--view", a.view,
      "frame the model from AZIMUTH,ELEVATION in degrees (0,0: from +z; 90,0: from +x); default 0,0 for a mesh");
  cmd->add_option("--size", a.size, "frame size WxH")->capture_default_str();
  cmd->add_option("--s", a.s, "two-pass tolight scale s (section 3.5), 1..127")->capture_default_str();
  cmd->add_option("--filter", a.filter, "normal-map sampling: nearest | bilinear")->capture_default_str();
  cmd->add_option("--specular", a.specular,
                  "specular instead of diffuse (section 3.7): half vectors, and the ILP raised to this power (1..256)");
  cmd->add_option("--lod-fade", a.lod_share,
                  "section 3.8's level of detail: every light becomes a co-located pair, the per-pixel light at "
                  "this share of its colour (nearest per channel) and a Gouraud-shaded light (gouraud's passes) at "
                  "the rest; 1 = per-pixel only, 0 = Gouraud only, a light at 0 % is left out. An engine sets it (see "
                  "--lod-distance) "
                  "from the object's distance. The other seeds' methods draw both halves their own way")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--lod-distance", a.lod_distance,
                  "section 3.8's fade by distance: NEAR,FAR in world units (a framed mesh: its radius); the share "
                  "--lod-fade takes is 1 with the camera at NEAR or nearer to the model's centre, 0 at FAR or beyond, "
                  "linear between (the paper leaves the mapping to the engine: this ramp is gsdot3's)");
  cmd->add_option(
         "--normal-map-bits", a.normal_map_bits,
         "bits per normal-map index (section 3.8's 4/8-bit maps): 8 = PSMT8 with 256 palette entries, 4 = "
         "PSMT4 with 16, quantised from the 8-bit map (the report's float reference reads the same 16 normals); "
         "24 = the map before quantisation, read by four-pass as three 8-bit maps, 128 + nearest(127·n) per axis "
         "(section 3.6), and by the float reference; the methods that read a texel's three components in one "
         "pass (two-pass, three-pass, 2002, the other seeds') read the 8-bit map")
      ->check(CLI::IsMember({4, 8, 24}))
      ->capture_default_str();
  cmd->add_flag("--spot-after-first-pass", a.spot_after_first_pass,
                "four-pass: a spot light's texture over the DPB after the first (sphere-map) pass instead of after all "
                "four (section 3.6 gives both)");
  cmd->add_flag("--floor", a.floor,
                "section 3.1's step 5: a floor under the model, not normal-mapped, drawn after step 4 into the same "
                "buffer as one generally would (per-vertex Lambert light of every light, Gouraud x the diffuse "
                "texture, Z-tested against the model and writing Z); exported by gsdot3 dump, priced by --cost");
  cmd->add_option("--path", a.path, "rasteriser path: cached (fast) | reference (re-rasterise every pass)")
      ->capture_default_str();
  cmd->add_option("--threads", a.threads, "frame bands rendered in parallel")->capture_default_str();
  cmd->add_flag(
      "--memory-path", a.memory_path,
      "frame buffers in the modelled GS local memory; post filter as PSMT8 channel-fetch sprites (same frames)");
  cmd->add_flag("--scalar", a.scalar,
                "every pixel through the scalar gs::pixel_pipeline instead of the SIMD units (gs_simd; same frames)");
  cmd->add_option("--dpb-clear", a.dpb_clear,
                  "step 2.1's DPB clear (section 3.4): explicit | z-trick | z-trick-psmz32 (Z-buffer clear during the "
                  "ILP pass; implies --memory-path, one thread; see --model-option texture_buffer=...)")
      ->capture_default_str();
  cmd->add_option("--draw-buffers", a.draw_buffers,
                  "section 3.1's draw buffers besides the output: 2 = the DPB and the LAB; 1 = the variant for too "
                  "little VRAM, at most 3 lights: the output is each light's DPB, then the LAB, each light's dot "
                  "layer and then the LAB's R, G, B kept in free alphas (the other display buffer's, the Z buffer's "
                  "top byte, the output's); same frames, other passes (gsdot3 dump writes them)")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  a.model.add_to(cmd);
}

std::function<scene_setup()> add_scene_options(CLI::App* cmd, pipeline::frame_use use) {
  auto a = std::make_shared<render_args>();
  add_options(cmd, *a);
  return [a, use] { return setup(*a, use); };
}

}  // namespace gsdot3::cli
