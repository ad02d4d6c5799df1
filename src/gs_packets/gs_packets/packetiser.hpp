// gs_packets/packetiser.hpp — cuts a GIF qword stream into GIF packets of bounded size, as a game's
// DMA chain hands them to the GIF: each packet is whole GIF tags with their data, ends with the one
// tag that has EOP = 1, and holds at most `max_bytes` bytes. A dump writes one transfer per packet.
//
// Why a bound (PCSX2, read with the search tool): `Gif_Unit::Gif_Unit` gives each GIF path a 9 MiB
// buffer (`Gif_Path::Init(path, 9 MiB, 1 MiB + 1 KiB)`: a 1 MiB + 1 KiB safe zone at its end), and
// `Gif_Path::CopyGSPacketData` copies a whole transfer into it (`GSDumpReplayer.cpp`,
// `GSDumpReplayerSendPacketToMTGS`); its size check is `pxAssertMsg`, absent from release builds,
// so a transfer over 9 MiB writes past the buffer. The default bound, 1 MiB, is below the safe zone.
//
// Where a tag is cut (a tag larger than the bound, or the rest of a packet too small for it):
// - PACKED: at a loop whose end is a primitive boundary of the current PRIM (the GS keeps PRIM and its
//   vertex queue across tags, so the second part's tag has PRE = 0 and the same REGS). A boundary:
//   POINT every vertex; LINE / SPRITE after an even count, TRIANGLE a multiple of 3 since the last PRIM
//   write; LINE_STRIP after 2 or more, TRIANGLE_STRIP / FAN after 3 or more (each further vertex
//   completes a primitive). Vertices are the XYZ2, XYZF2, XYZ3, XYZF3 writes (descriptor or A+D).
//   A tag without vertices is cut at any loop.
// - REGLIST: at a loop where NLOOP × NREG is even (whole qwords). IMAGE: at any qword (the transfer
//   continues with the next IMAGE tag, TRXDIR unchanged).
// An EOP in the input ends a packet there too. Throws std::invalid_argument for a bound under 32
// bytes, a tag that cannot be cut small enough, or a stream that is not whole tags.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace gs::packets {

inline constexpr std::size_t default_max_packet_bytes = std::size_t{1} << 20;  // 1 MiB
// PCSX2's GIF path buffer (Gif_Unit::Gif_Unit): no transfer may exceed it.
inline constexpr std::size_t pcsx2_path_buffer_bytes = std::size_t{9} << 20;

std::vector<std::vector<std::uint8_t>> split_gif_packets(std::span<const std::uint8_t> stream,
                                                         std::size_t max_bytes = default_max_packet_bytes);

}  // namespace gs::packets
