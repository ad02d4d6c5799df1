// proofs_triangle — re-derives the stored verdicts of two-pass.max-s.interpolated's triangle search
// (src/proofs): the certificate rows of two_pass_triangle/certificates.csv, the relaxation witnesses of
// triangle_relaxation.cpp and the certified bound of relaxation_classes.hpp. Not a test and not
// part of `gsdot3 prove`: the tool that finds what the ledger stores (tools/README.md lists which
// subcommand re-derives which row). Built with -DGSDOT3_TOOLS=ON.
#include <CLI/CLI.hpp>

#include "triangle_args.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "Re-derives the triangle certificates, relaxation witnesses and certified bound of two-pass.max-s.interpolated"};
  app.require_subcommand(1);
  app.footer("Each subcommand prints its usage with --help; tools/README.md says which stored row each re-derives.");
  int rc = 0;
  gsdot3::tools::add_search_command(app, rc);
  gsdot3::tools::add_two_axis_command(app, rc);
  gsdot3::tools::add_corner_command(app, rc);
  gsdot3::tools::add_steep_command(app, rc);
  gsdot3::tools::add_boxes_command(app, rc);
  gsdot3::tools::add_relaxation_command(app, rc);
  gsdot3::tools::add_certify_command(app, rc);
  CLI11_PARSE(app, argc, argv);
  return rc;
}
