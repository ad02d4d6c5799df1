// triangle_args.hpp — what the subcommands of tools/proofs_triangle share: the light scale S and the
// gouraud_fraction every search runs under, a progress line for the long runs, and the functions that
// add each subcommand to the command line (one source file each).
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>

#include "gs_arith/options.hpp"

namespace gsdot3::tools {

// `S [--truncate-to-8]`, S in 1..127. The searches run under gouraud_setup=plane_steps, the set-up
// whose lag the certificates exploit (the model's default is per_pixel), unless they set another.
struct search_args {
  int s = 0;
  bool truncate = false;
  gs::gouraud_setup setup = gs::gouraud_setup::plane_steps;
  gs::model_options options() const {
    gs::model_options o{};
    o.setup = setup;
    if (truncate) o.gouraud = gs::gouraud_fraction::truncate_to_8;
    return o;
  }
  const char* option_name() const { return truncate ? "truncate_to_8" : "keep_fraction"; }
};

inline void add_search_args(CLI::App& cmd, search_args& a) {
  cmd.add_option("S", a.s, "The light scale s: the vertex lights are packed lights of L_s")
      ->required()
      ->check(CLI::Range(1, 127));
  cmd.add_flag("--truncate-to-8", a.truncate, "Run under gouraud_fraction=truncate_to_8 (default keep_fraction)");
}

// A line on stderr at most every five seconds: `what: done of total`.
class progress {
 public:
  progress(const char* what, long long total) : what_(what), total_(total), last_(std::chrono::steady_clock::now()) {}
  void at(long long done) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::seconds(5)) return;
    last_ = now;
    std::fprintf(stderr, "%s: %lld of %lld\n", what_, done, total_);
  }

 private:
  const char* what_;
  long long total_;
  std::chrono::steady_clock::time_point last_;
};

// Each adds its subcommand to `app`; its callback leaves the process's exit status in `rc`.
void add_search_command(CLI::App& app, int& rc);
void add_two_axis_command(CLI::App& app, int& rc);
void add_corner_command(CLI::App& app, int& rc);
void add_steep_command(CLI::App& app, int& rc);
void add_boxes_command(CLI::App& app, int& rc);
void add_relaxation_command(CLI::App& app, int& rc);
void add_certify_command(CLI::App& app, int& rc);

}  // namespace gsdot3::tools
