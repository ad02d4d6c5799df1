// gsdot3 dump-info — what a PCSX2 GS dump (.gs, .gs.xz, .gs.zst) holds: the header, the state blob's
// registers (version 8), packet counts and the GIF tags of each path.
#include <array>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "dump_notes.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/state.hpp"

namespace gsdot3::cli {
namespace {

namespace dump = gs::dump;
namespace pk = gs::packets;

std::string hex(std::uint64_t v, int digits = 16) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%0*llx", digits, static_cast<unsigned long long>(v));
  return buf;
}

void run(const std::string& file) {
  dump::gs_dump d;
  std::vector<dump::path_stream> paths;
  try {
    d = dump::load_dump(file);
  } catch (const dump::dump_error& e) { throw usage_error(e.what()); }
  try {
    paths = dump::decode_paths(d);
  } catch (const dump::dump_error& e) { throw usage_error(file + ": " + e.what()); }
  std::cout << "file " << file << "\n"
            << "layout " << (d.new_layout ? "new (0xFFFFFFFF, GSDumpHeader)" : "old (CRC, state size)") << "\n"
            << "state_version " << d.state_version << "\n"
            << "state_size " << d.state.size() << "\n"
            << "crc " << hex(d.crc, 8) << "\n"
            << "serial \"" << d.serial << "\"\n"
            << "screenshot " << d.screenshot_width << "x" << d.screenshot_height << "\n";
  if (const auto layout = dump::state_layout(d.state_version, d.state.size())) {
    std::size_t nonzero = 0;
    const std::uint32_t memory = dump::find_field(*layout, "memory")->offset;
    for (std::uint32_t i = 0; i < dump::memory_bytes; ++i) nonzero += d.state[memory + i] != 0;
    for (const auto& f : *layout) {
      if (f.name == "memory") {
        std::cout << "state memory: " << nonzero << " of " << dump::memory_bytes << " bytes non-zero\n";
      } else if (f.size > 16) {
        std::cout << "state " << f.name << ": " << f.size << " bytes (not decoded)\n";
      } else if (f.size == 16) {
        const dump::state_field lo{f.name, f.offset, 8}, hi{f.name, f.offset + 8, 8};
        std::cout << "state " << f.name << " = " << hex(dump::state_get(d.state, hi)) << "_"
                  << hex(dump::state_get(d.state, lo)).substr(2) << "\n";
      } else {
        std::cout << "state " << f.name << " = " << hex(dump::state_get(d.state, f), static_cast<int>(2 * f.size))
                  << "\n";
      }
    }
  } else {
    std::cout << "state fields: not decoded (the layout of version " << d.state_version << " is not known; 0..9 are)\n";
  }
  std::array<std::size_t, 4> by_type{}, transfers{};
  for (const auto& p : d.packets) {
    ++by_type[static_cast<std::size_t>(p.type)];
    if (p.type == dump::packet_type::transfer) ++transfers[p.path];
  }
  std::cout << "packets " << d.packets.size() << ": transfer " << by_type[0] << " (path 0: " << transfers[0]
            << ", 1: " << transfers[1] << ", 2: " << transfers[2] << ", 3: " << transfers[3] << "), vsync "
            << by_type[1] << ", readFIFO2 " << by_type[2] << ", registers " << by_type[3] << "\n";
  for (unsigned i = 0; i < 4; ++i) {
    std::array<std::size_t, 3> flg{};
    std::size_t tags = 0, writes = 0, image_qwords = 0;
    for (const auto& e : paths[i].events) {
      if (e.what == pk::gif_event::kind::tag) ++tags, ++flg[static_cast<std::size_t>(e.tag.FLG)];
      if (e.what == pk::gif_event::kind::reg_write) ++writes;
      if (e.what == pk::gif_event::kind::image) image_qwords += e.data.size() / 16;
    }
    std::cout << "path " << i << ": " << tags << " GIF tags (PACKED " << flg[0] << ", REGLIST " << flg[1] << ", IMAGE "
              << flg[2] << "), " << writes << " register writes (" << paths[i].unused_writes
              << " to unused addresses), " << image_qwords << " IMAGE qwords\n";
  }
  std::cout << "notices " << d.notices.size() << "\n";
  print_dump_notes(file, d, paths);
}

}  // namespace

void add_dump_info_command(CLI::App& app, context&) {
  auto file = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("dump-info",
                                 "What a PCSX2 GS dump (.gs, .gs.xz, .gs.zst) holds: header, state "
                                 "registers, packet counts, GIF tags per path");
  cmd->add_option("FILE", *file, "The dump")->required();
  cmd->callback([file] { run(*file); });
}

}  // namespace gsdot3::cli
