// cli/import_options.cpp — the mesh import options (see import_options.hpp).
#include "import_options.hpp"

#include <cstdio>
#include <string>

#include "commands.hpp"

namespace gsdot3::cli {

void add_import_options(CLI::App* cmd, import_args& a) {
  cmd->add_option("--normals", a.normals,
                  "normals generated for a mesh without them: smooth (angle-weighted, split across edges sharper "
                  "than --crease-angle, as modelling tools do) | flat (each triangle its own)")
      ->capture_default_str();
  cmd->add_option("--crease-angle", a.crease_angle,
                  "with --normals smooth: an edge whose two faces' normals differ by more than DEGREES (0..180) "
                  "is hard, each face keeps its own normal there (default 60; 180: smooth across every edge)")
      ->type_name("DEGREES");
  cmd->add_option("--uv-projection", a.uv_projection,
                  "UVs for a mesh without them: box | sphere | planar (default: chosen for the shape, planar when it "
                  "faces one axis, sphere when it faces away from its centre, else box; named in a notice)");
  cmd->add_option("--tangents", a.tangents,
                  "auto (the file's tangents, e.g. glTF TANGENT, else MikkTSpace) | mikktspace (always computed)")
      ->capture_default_str();
  cmd->add_option(
         "--duplicates", a.duplicates,
         "triangles with the positions and winding of an earlier one: drop (each surface drawn once) | keep (drawn "
         "twice: every GS pass that blends into the frame, Cs + Cd, Cd - Cs, (Cs - Cd)*As + Cd with COLCLAMP off, "
         "applies twice and wraps modulo 256; the float reference is unaffected). Counted either way")
      ->capture_default_str();
}

pipeline::import_options parse_import_options(const import_args& a) {
  pipeline::import_options import;
  if (a.normals != "smooth" && a.normals != "flat")
    throw usage_error("--normals: expected flat or smooth, got '" + a.normals + "'");
  import.normals = a.normals == "flat" ? pipeline::normals_mode::flat : pipeline::normals_mode::smooth;
  if (a.crease_angle) {
    if (!(*a.crease_angle >= 0.0 && *a.crease_angle <= 180.0)) {
      char got[32];
      std::snprintf(got, sizeof got, "%g", *a.crease_angle);
      throw usage_error(std::string("--crease-angle: expected 0..180 degrees, got ") + got);
    }
    if (import.normals == pipeline::normals_mode::flat)
      throw usage_error("--crease-angle: applies to --normals smooth, not flat");
    import.crease_degrees = static_cast<float>(*a.crease_angle);
  }
  if (!a.uv_projection.empty()) {
    if (a.uv_projection == "box")
      import.uvs = pipeline::uv_projection::box;
    else if (a.uv_projection == "sphere")
      import.uvs = pipeline::uv_projection::sphere;
    else if (a.uv_projection == "planar")
      import.uvs = pipeline::uv_projection::planar;
    else
      throw usage_error("--uv-projection: expected box, sphere or planar, got '" + a.uv_projection + "'");
  }
  if (a.tangents != "auto" && a.tangents != "mikktspace")
    throw usage_error("--tangents: expected auto or mikktspace, got '" + a.tangents + "'");
  import.tangents = a.tangents == "auto" ? pipeline::tangent_mode::automatic : pipeline::tangent_mode::mikktspace;
  if (a.duplicates != "drop" && a.duplicates != "keep")
    throw usage_error("--duplicates: expected drop or keep, got '" + a.duplicates + "'");
  import.duplicates = a.duplicates == "drop" ? pipeline::duplicates_mode::drop : pipeline::duplicates_mode::keep;
  return import;
}

}  // namespace gsdot3::cli
