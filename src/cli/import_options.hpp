// cli/import_options.hpp — how a mesh file is imported (--normals, --crease-angle, --uv-projection,
// --tangents, --duplicates): one description for every command that reads a mesh (render, report, dump,
// mesh-info).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "pipeline/mesh_import.hpp"

namespace gsdot3::cli {

struct import_args {
  std::string normals = "smooth", uv_projection, tangents = "auto", duplicates = "drop";
  std::optional<double> crease_angle;  // unset: pipeline::import_options' default
};

void add_import_options(CLI::App* cmd, import_args& a);

// Throws usage_error for a value the option does not take.
pipeline::import_options parse_import_options(const import_args& a);

}  // namespace gsdot3::cli
