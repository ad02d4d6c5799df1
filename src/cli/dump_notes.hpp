// cli/dump_notes.hpp — what dump-info and replay both say about a dump read leniently: each notice
// (gs_packets/dump.hpp: one per leniency, named, with its byte) on stderr, and per path the register
// writes to addresses no GS register has, on stdout.
#pragma once

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "gs_packets/dump.hpp"

namespace gsdot3::cli {

inline void print_dump_notes(const std::string& file, const gs::dump::gs_dump& d,
                             const std::vector<gs::dump::path_stream>& paths) {
  for (const auto& n : d.notices) std::cerr << "gsdot3: notice: " << file << ": " << gs::dump::describe(n) << "\n";
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (paths[i].unused_writes == 0) continue;
    char address[8];
    std::snprintf(address, sizeof address, "0x%02X", paths[i].first_unused_address);
    std::cout << "path " << i << ": " << paths[i].unused_writes
              << " register writes to unused addresses (first: " << address << " at byte "
              << paths[i].first_unused_offset << "), ignored as PCSX2 ignores them\n";
  }
}

}  // namespace gsdot3::cli
