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

}  // namespace gsdot3::bench
