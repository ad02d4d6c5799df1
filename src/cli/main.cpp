// gsdot3 — command-line entry: subcommands are registered from commands.hpp.
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "pipeline/files.hpp"

int main(int argc, char** argv) {
  CLI::App app{"gsdot3 — bit-exact fixed-point verification of DOT3 normal mapping on the PS2 GS"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "gsdot3 0.1.0");
  gsdot3::cli::context ctx;
  gsdot3::cli::add_alu_command(app, ctx);
  gsdot3::cli::add_normal_encoding_command(app, ctx);
  gsdot3::cli::add_mem_command(app, ctx);
  gsdot3::cli::add_mesh_info_command(app, ctx);
  gsdot3::cli::add_prove_command(app, ctx);
  gsdot3::cli::add_pvr_bump_command(app, ctx);
  gsdot3::cli::add_quality_command(app, ctx);
  gsdot3::cli::add_render_command(app, ctx);
  gsdot3::cli::add_ssbump_command(app, ctx);
  gsdot3::cli::add_vectors_command(app, ctx);
  gsdot3::cli::add_dump_info_command(app, ctx);
  gsdot3::cli::add_compare_command(app, ctx);
  gsdot3::cli::add_replay_command(app, ctx);
  gsdot3::cli::add_probe_command(app, ctx);
  gsdot3::cli::add_dump_command(app, ctx);
  gsdot3::cli::add_cost_command(app, ctx);
  // A repeatable option takes one value per occurrence, so `--option a=b FILE` leaves FILE positional.
  auto one_value_each = [](CLI::App* a, auto& self) -> void {
    for (CLI::Option* opt : a->get_options()) opt->allow_extra_args(false);
    for (CLI::App* sub : a->get_subcommands({})) self(sub, self);
  };
  one_value_each(&app, one_value_each);
  gsdot3::pipeline::remove_staging_on_signals();  // an interrupted run leaves no --out staging folder
  std::string commands;
  bool known = false;
  for (CLI::App* sub : app.get_subcommands({})) {
    commands += (commands.empty() ? "" : ", ") + sub->get_name();
    known = known || (argc > 1 && sub->check_name(argv[1]));
  }
  if (argc < 2) {
    std::cerr << "gsdot3: error: give a command (" << commands << "; gsdot3 CMD --help)\n";
    return 2;
  }
  if (argv[1][0] != '-' && !known) {
    std::cerr << "gsdot3: error: unknown command '" << argv[1] << "' (commands: " << commands << ")\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) { return app.exit(e); } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) { return app.exit(e); } catch (const CLI::ParseError& e) {
    std::cerr << "gsdot3: error: " << e.what() << " (see --help)\n";
    return 2;
  } catch (const gsdot3::cli::usage_error& e) {
    std::cerr << "gsdot3: error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {  // the libraries' word for bad input (their bugs throw logic_error)
    std::cerr << "gsdot3: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "gsdot3: internal error: " << e.what() << "\n";
    return 3;
  }
  return ctx.exit_code;
}
