// cli/commands.hpp — the gsdot3 subcommands. Each lives in its own file and registers itself on
// the CLI11 app; main.cpp only calls the add_* functions and maps errors to exit codes.
#pragma once

#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

namespace gsdot3::cli {

// Set by the subcommand that ran; main returns it.
struct context {
  int exit_code = 0;
};

// Bad input from the user (malformed value, unknown name, unreadable file): main prints
// "gsdot3: error: <what>" on one line of stderr and exits 2.
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One line per subcommand (alphabetical).
void add_alu_command(CLI::App& app, context& ctx);
void add_normal_encoding_command(CLI::App& app, context& ctx);
void add_mem_command(CLI::App& app, context& ctx);
void add_mesh_info_command(CLI::App& app, context& ctx);  // a mesh file as the importer reads it
void add_prove_command(CLI::App& app, context& ctx);
void add_pvr_bump_command(CLI::App& app, context& ctx);  // seed 004 bump textures
void add_quality_command(CLI::App& app, context& ctx);   // seed 000 comparative quality sentences
void add_render_command(CLI::App& app, context& ctx);    // render and report
void add_ssbump_command(CLI::App& app, context& ctx);
void add_vectors_command(CLI::App& app, context& ctx);
void add_dump_info_command(CLI::App& app, context& ctx);  // PCSX2 GS dumps
void add_compare_command(CLI::App& app, context& ctx);    // two frames, pixel by pixel
void add_replay_command(CLI::App& app, context& ctx);     // a GS dump through the model
void add_probe_command(CLI::App& app, context& ctx);      // the option probe and its decoder
void add_dump_command(CLI::App& app, context& ctx);       // a method's frame as a GS dump
void add_cost_command(CLI::App& app, context& ctx);       // a GS dump priced on the console's GS

}  // namespace gsdot3::cli
