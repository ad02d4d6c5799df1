// proofs_search_args.hpp — the command line the triangle certificate searches share:
// `TOOL S [truncate_to_8] [MORE...]`, S in 1..127.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gs_arith/options.hpp"

namespace gsdot3::bench {

struct search_args {
  int s = 0;
  gs::model_options o{};
  int next = 2;  // index of the first argument after S [truncate_to_8]
  const char* option_name() const {
    return o.gouraud == gs::gouraud_fraction::truncate_to_8 ? "truncate_to_8" : "keep_fraction";
  }
};

// Exits with status 2 and a usage line on stderr when S is missing or out of range.
inline search_args parse_search_args(int argc, char** argv, const char* tool, const char* more = "") {
  search_args a;
  if (argc >= 2) a.s = std::atoi(argv[1]);
  if (argc > 2 && std::strcmp(argv[2], "truncate_to_8") == 0) a.o.gouraud = gs::gouraud_fraction::truncate_to_8, a.next = 3;
  if (a.s < 1 || a.s > 127) {
    std::fprintf(stderr, "usage: %s S [truncate_to_8]%s (S in 1..127)\n", tool, more);
    std::exit(2);
  }
  return a;
}

// `IX IY SIDE THIRD [F_MIN] [TOP]` after `S [truncate_to_8]`, the steep construction's normal, wrap side
// and third channel (proofs_triangle_lattice, proofs_triangle_free_x); exits with status 2 on bad usage.
struct steep_args {
  int iX = 0, iY = 0, side = 0, third = 0;
  double f_min = 0;
  int top = 0;
};
inline steep_args parse_steep_args(int argc, char** argv, const search_args& a, const char* tool, const char* usage, int default_top) {
  const int at = a.next;
  if (argc < at + 4) {
    std::fprintf(stderr, "usage: %s S [truncate_to_8] %s\n", tool, usage);
    std::exit(2);
  }
  steep_args r{std::atoi(argv[at]), std::atoi(argv[at + 1]), std::atoi(argv[at + 2]), std::atoi(argv[at + 3]),
               argc > at + 4 ? std::atof(argv[at + 4]) : 0, argc > at + 5 ? std::atoi(argv[at + 5]) : default_top};
  if ((r.side != 1 && r.side != -1) || r.third < 0 || r.third > 2 || r.top < 1) {
    std::fprintf(stderr, "%s: SIDE 1 or -1, THIRD 0..2, TOP >= 1\n", tool);
    std::exit(2);
  }
  return r;
}

}  // namespace gsdot3::bench
