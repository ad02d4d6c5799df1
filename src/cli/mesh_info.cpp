// gsdot3 mesh-info — what the importer read from a mesh file, what it repaired and what it
// generated, with the import options render takes; optionally the result as .glb.
#include <iostream>
#include <string>

#include "commands.hpp"
#include "import_options.hpp"
#include "pipeline/mesh_export.hpp"
#include "pipeline/mesh_info.hpp"

namespace gsdot3::cli {

void add_mesh_info_command(CLI::App& app, context& ctx) {
  struct args {
    std::string file, export_mesh;
    bool json = false;
    import_args import;
  };
  auto a = std::make_shared<args>();
  auto* cmd =
      app.add_subcommand("mesh-info",
                         "What the importer read from a mesh file (as render --mesh reads it), what it repaired and "
                         "generated: counts, bounds, UV area, tangent source and handedness, duplicates, notices");
  cmd->add_option("FILE", a->file, "mesh file (OBJ, glTF 2.0, PLY, FBX, Collada, ... as assimp 5.2 reads them)")
      ->required();
  cmd->add_flag("--json", a->json,
                "one JSON object (report.json's input.mesh, plus vertices, bounds, UV area, tangent w counts)");
  cmd->add_option(
      "--export-mesh", a->export_mesh,
      "also write the imported mesh (model space) as OUT.glb: NORMAL, TANGENT (w = handedness) and TEXCOORD_0");
  add_import_options(cmd, a->import);
  cmd->callback([a, &ctx] {
    pipeline::import_options options = parse_import_options(a->import);
    options.describe_empty = true;  // a file with nothing to draw is described all the same
    pipeline::imported_mesh im;
    try {
      im = pipeline::import_mesh(a->file, options);
      if (!a->export_mesh.empty() && im.model.triangles.empty())
        throw std::runtime_error(a->file + ": --export-mesh: no triangles to export");
      if (!a->export_mesh.empty()) pipeline::export_mesh_glb(im.model, a->export_mesh);
    } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
    const pipeline::mesh_figures f = pipeline::measure(im.model);
    std::cout << (a->json ? pipeline::mesh_info_json(im, f) + "\n" : pipeline::mesh_info_text(im, f));
    if (!a->export_mesh.empty()) std::cerr << "gsdot3: wrote " << a->export_mesh << "\n";
    ctx.exit_code = 0;
  });
}

}  // namespace gsdot3::cli
