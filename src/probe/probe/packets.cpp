// probe/packets.cpp — the probe's GIF stream and GS dump (see packets.hpp).
#include "probe/packets.hpp"

#include <array>
#include <utility>

#include "gs_arith/registers.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/packetiser.hpp"
#include "gs_packets/register_values.hpp"
#include "gs_packets/video_mode.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/state.hpp"
#include "probe/design.hpp"

namespace gsdot3::probe {
namespace {

namespace pk = gs::packets;
using write = std::pair<std::uint8_t, std::uint64_t>;

// The state registers of a draw, in the order they are written (PRIM last: it resets the vertex queue).
std::vector<write> state_writes(const draw& d) {
  const gs::gs_registers& r = d.regs;
  return {{0x06, gs::encode(r.TEX0_1)},
          {0x14, pk::tex1_value(d.linear, false)},
          {0x40, pk::scissor_value(d.scissor.x0, d.scissor.x1, d.scissor.y0, d.scissor.y1)},
          {0x42, gs::encode(r.ALPHA_1)},
          {0x47, gs::encode(r.TEST_1)},
          {0x4C, gs::encode(r.FRAME_1)},
          {0x46, gs::encode(r.COLCLAMP)},
          {0x49, gs::encode(r.PABE)},
          {0x4A, gs::encode(r.FBA_1)},
          {0x45, gs::encode(r.DTHE)},
          {0x44, gs::encode(r.DIMX)},
          {0x00, gs::encode(r.PRIM)}};
}

void add_texture_upload(pk::packet_builder& pb, const std::vector<std::uint32_t>& texels) {
  gs::mem::bitbltbuf_reg b;
  b.DBP = fixed::uint<14>::from_wrapped(texture_page * 32);
  b.DBW = fixed::uint<6>::from_wrapped(1);
  gs::mem::trxreg_reg size;
  size.RRW = size.RRH = fixed::uint<12>::from_wrapped(texture_side);
  const write regs[] = {{pk::reg::BITBLTBUF, gs::mem::encode(b)},
                        {pk::reg::TRXPOS, gs::mem::encode(gs::mem::trxpos_reg{})},
                        {pk::reg::TRXREG, gs::mem::encode(size)},
                        {pk::reg::TRXDIR, gs::mem::encode(gs::mem::trxdir_reg{})}};
  pb.ad(regs);
  std::vector<std::uint8_t> bytes;
  for (const std::uint32_t t : texels)
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<std::uint8_t>(t >> (8 * k)));
  pb.image(bytes);
}

}  // namespace

display_registers probe_display() {
  namespace D = gs::regs::DISPLAY;
  using gs::regs::encode;
  const std::uint64_t dispfb = pk::dispfb_value(0, frame_fbw);
  const std::uint64_t display = encode(D::DX, 636) | encode(D::DY, 50) | encode(D::MAGH, 3) |
                                encode(D::DW, 4 * frame_width - 1) | encode(D::DH, frame_height - 1);
  return {pk::pmode_circuit1(), 1, dispfb, display};
}

pk::packet_builder probe_packets() {
  const design& des = probe_design();
  pk::packet_builder pb;
  const gs::zbuf_reg zbuf{fixed::uint<9>::from_wrapped(200), gs::zbuf_psm::PSMZ32, true};  // ZMSK = 1: no Z writes
  const write setup[] = {{0x18, 0}, {0x1A, 1}, {0x4E, gs::encode(zbuf)}};  // XYOFFSET_1, PRMODECONT, ZBUF_1
  pb.ad(setup);
  add_texture_upload(pb, des.texture);
  std::vector<write> last;
  for (std::size_t i = 0; i < des.draws.size(); ++i) {
    const draw& d = des.draws[i];
    std::vector<write> changed;
    if (d.texflush) changed.push_back({0x3F, 0});  // TEXFLUSH
    const std::vector<write> now = state_writes(d);
    for (std::size_t k = 0; k < now.size(); ++k)
      if (last.empty() || now[k] != last[k]) changed.push_back(now[k]);
    last = now;
    if (!changed.empty()) pb.ad(changed);
    std::vector<pk::qword> data;
    for (const vertex& v : d.v) {
      data.push_back(pk::packed_rgba(static_cast<std::uint8_t>(v.rgba), static_cast<std::uint8_t>(v.rgba >> 8),
                                     static_cast<std::uint8_t>(v.rgba >> 16), static_cast<std::uint8_t>(v.rgba >> 24)));
      data.push_back(pk::packed_uv(static_cast<std::uint32_t>(v.u16), static_cast<std::uint32_t>(v.v16)));
      data.push_back(
          pk::packed_xyz2(static_cast<std::uint16_t>(v.x * 16), static_cast<std::uint16_t>(v.y * 16), 0, false));
    }
    const unsigned regs[] = {pk::desc::RGBAQ, pk::desc::UV, pk::desc::XYZ2};
    pb.packed(std::nullopt, regs, data, i + 1 == des.draws.size());
  }
  return pb;
}

gs::dump::gs_dump probe_dump() {
  gs::dump::gs_dump d;
  d.state_version = gs::dump::state_version_written;
  d.serial = "GSDOT3-PROBE";
  d.state = gs::dump::make_state_v8();
  const display_registers r = probe_display();
  auto put = [&](std::size_t offset, std::uint64_t v) {
    for (int b = 0; b < 8; ++b)
      d.privileged[offset + static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(v >> (8 * b));
  };
  put(0x0000, r.PMODE);
  // The NTSC video mode's SMODE1 and SYNCV (gs_packets/video_mode.hpp): with SMODE1 = 0 PCSX2 reports VESA.
  put(gs::packets::SMODE1_offset, gs::packets::encode(gs::packets::smode1_for(gs::packets::video_mode::ntsc)));
  put(0x0020, r.SMODE2);
  put(gs::packets::SYNCV_offset, gs::packets::encode(gs::packets::syncv_for(gs::packets::video_mode::ntsc)));
  put(0x0070, r.DISPFB1);
  put(0x0080, r.DISPLAY1);
  for (auto& packet : gs::packets::split_gif_packets(probe_packets().bytes()))
    d.packets.push_back({gs::dump::packet_type::transfer, 2, 0, 0, std::move(packet), 0});
  d.packets.push_back({gs::dump::packet_type::registers, 0, 0, 0, d.privileged, 0});
  d.packets.push_back({gs::dump::packet_type::vsync, 0, 1, 0, {}, 0});
  gs::dump::assign_offsets(d);
  return d;
}

}  // namespace gsdot3::probe
