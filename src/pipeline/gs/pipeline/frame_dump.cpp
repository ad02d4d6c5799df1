// frame_dump: a frame's GIF packets as a .gs dump (moved out of frame_packets.cpp to keep both files
// under 400 lines): the privileged registers (PMODE, SMODE1/2, SYNCV, DISPFB1, DISPLAY1) at their
// offsets, the GIF stream split into PATH3 transfers, then the registers packet and one vsync.
#include <string>
#include <utility>
#include <vector>

#include "gs_packets/dump.hpp"
#include "gs_packets/packetiser.hpp"
#include "gs_packets/state.hpp"
#include "gs_packets/video_mode.hpp"
#include "pipeline/frame_packets.hpp"

namespace gsdot3::pipeline {

namespace pk = gs::packets;

gs::dump::gs_dump frame_dump(const frame_packets& fp, const dump_layout& layout) {
  gs::dump::gs_dump d;
  d.new_layout = true;
  d.state_version = gs::dump::state_version_written;
  d.serial = "gsdot3";
  d.state = gs::dump::make_state_v8();
  auto put = [&](std::uint32_t offset, std::uint64_t v) {
    for (std::uint32_t b = 0; b < 8; ++b) d.privileged[offset + b] = static_cast<std::uint8_t>(v >> (8 * b));
  };
  put(PMODE_offset, fp.PMODE);
  put(pk::SMODE1_offset, pk::encode(pk::smode1_for(layout.video)));
  put(pk::SMODE2_offset, pk::smode2_for(layout.video));
  put(pk::SYNCV_offset, pk::encode(pk::syncv_for(layout.video)));
  put(DISPFB1_offset, fp.DISPFB1);
  put(DISPLAY1_offset, pk::display_for(layout.video, fp.width, fp.height));
  for (std::vector<std::uint8_t>& packet : pk::split_gif_packets(fp.gif, layout.max_packet_bytes)) {
    gs::dump::packet transfer;
    transfer.type = gs::dump::packet_type::transfer;
    transfer.path = 2;  // PATH3
    transfer.data = std::move(packet);
    d.packets.push_back(std::move(transfer));
  }
  gs::dump::packet regs;
  regs.type = gs::dump::packet_type::registers;
  regs.data = d.privileged;
  d.packets.push_back(std::move(regs));
  gs::dump::packet vsync;
  vsync.type = gs::dump::packet_type::vsync;
  d.packets.push_back(std::move(vsync));
  gs::dump::assign_offsets(d);
  return d;
}

}  // namespace gsdot3::pipeline
