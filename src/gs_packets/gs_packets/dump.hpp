// gs_packets/dump.hpp — the PCSX2 GS dump container (.gs; .gs.xz / .gs.zst compressed whole).
//
// Layout, read with the search tool from PCSX2 `pcsx2/GS/GSDump.cpp` (`GSDumpBase::AddHeader`,
// `Transfer`, `ReadFIFO`, `VSync`) and `pcsx2/GS/GSDump.h` (`struct GSDumpHeader`, #pragma pack 4);
// all integers little-endian:
//   new layout: u32 0xFFFFFFFF, u32 header_size, GSDumpHeader {state_version, state_size,
//               serial_offset, serial_size, crc, screenshot_width, screenshot_height,
//               screenshot_offset, screenshot_size} (9 × u32 = 36 bytes); serial and an RGBA
//               screenshot at their offsets from the start of GSDumpHeader, all within header_size
//               (AddHeader: header_size = 36 + serial size + screenshot size; serial_offset = 36;
//               screenshot_offset = 36 + serial size); then the state blob (state_size bytes).
//   old layout (the first u32 is not 0xFFFFFFFF): u32 crc, u32 state_size, the state blob.
//   both: the 8 KiB privileged registers (GSPrivRegSet), then packets, each a type byte:
//     0 transfer  [path u8][size u32][size bytes]  (path 0 = PATH1 old, 1 PATH2, 2 PATH3, 3 PATH1 new:
//                 ../shared/spec/gs-memory-facts.md "GS dumps"; GSDumpBase::Transfer writes the index it is given)
//     1 vsync     [field u8]
//     2 readFIFO2 [size u32]
//     3 registers [8 KiB privileged registers]
//   VSync writes a registers packet then a vsync packet.
// The state blob itself: state.hpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "gs_packets/decoder.hpp"

namespace gs::dump {

struct dump_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t new_layout_marker = 0xFFFFFFFFu;
inline constexpr std::uint32_t header_bytes = 36;  // sizeof(GSDumpHeader): nine u32, pack 4
inline constexpr std::uint32_t privileged_bytes = 8192;

enum class packet_type : std::uint8_t { transfer = 0, vsync = 1, read_fifo2 = 2, registers = 3 };

struct packet {
  packet_type type = packet_type::transfer;
  std::uint8_t path = 0;           // transfer
  std::uint8_t field = 0;          // vsync
  std::uint32_t size = 0;          // read_fifo2
  std::vector<std::uint8_t> data;  // transfer data, or the 8 KiB registers
  std::uint64_t offset = 0;        // byte offset of the type byte in the (uncompressed) dump; set by
                                   // read_dump, or by assign_offsets for a dump built in memory
};

// What read_dump accepted that a strict reader would refuse, as PCSX2 accepts it (one per leniency):
//   truncated_last_packet  the last packet's body runs past the end: dropped (PCSX2 GSDumpFile::ReadFile:
//                          "Dropping last packet of N bytes (we only have M bytes)"); a cut packet header
//                          is refused, as ReadFile returns false there
//   screenshot_ignored     screenshot fields that are not width × height × 4 bytes within the header:
//                          the screenshot is dropped (ReadFile never reads them; GetPreviewImageFromDump
//                          shows no preview for them)
//   transfer_path_skipped  a transfer whose path byte is above 3: skipped (GSDumpReplayerCpuStep's
//                          switch on the path has no case for it)
//   state_version_differs  the header's state_version differs from the blob's: the blob's is used
//                          (ReadFile does not read the header's; GSState::Defrost reads the blob's)
// and one of gsdot3's own:
//   gsdot3_state_layout    a version-8 state of state_size_gsdot3_v8 bytes, gsdot3's layout before issue 57
//                          (state.hpp): read in that layout
struct notice {
  std::string name;
  std::uint64_t offset = 0;  // byte of the dump (uncompressed) it is about
  std::string text;
};

struct gs_dump {
  bool new_layout = true;
  std::uint32_t crc = 0;
  std::uint32_t state_version = 0;  // new layout: the header's; old: the state blob's first u32
  std::string serial;
  std::uint32_t screenshot_width = 0, screenshot_height = 0;
  std::vector<std::uint8_t> screenshot;  // RGBA, width × height × 4 bytes
  std::vector<std::uint8_t> state;
  std::vector<std::uint8_t> privileged = std::vector<std::uint8_t>(privileged_bytes, 0);
  std::vector<packet> packets;
  std::vector<notice> notices;  // set by read_dump; not written
};

// Serialises in the new layout (old-layout dumps are read, not written). Throws dump_error when the
// dump cannot be represented (screenshot size ≠ width × height × 4, registers not 8 KiB).
std::vector<std::uint8_t> write_dump(const gs_dump& d);
// Sets every packet's offset to the byte write_dump writes its type byte at. A dump built in memory
// needs it before decode_paths or a replay, which order the packets and name faults by these offsets.
void assign_offsets(gs_dump& d);
// Parses either layout; malformed input throws dump_error with one line naming the byte offset. What
// PCSX2 refuses is refused with its reason: a state version above 9 ("GS: Savestate version is
// incompatible.  Load aborted.", GSState::Defrost, STATE_VERSION 9), a serial outside the header
// ("GSDump header is corrupted.", ReadFile). What it accepts is read, with a notice (above).
gs_dump read_dump(std::span<const std::uint8_t> bytes);
// One line for a notice: "byte N: NAME: text".
std::string describe(const notice& n);

// The GIF stream of each path: the path's transfers in order, concatenated (a packet may continue
// from one transfer into the next), decoded. A GIF fault throws dump_error naming the transfer
// packet and its byte offset in the dump.
struct path_stream {
  std::vector<std::uint8_t> bytes;
  std::vector<packets::gif_event> events;   // image data points into bytes
  std::vector<std::uint64_t> file_offsets;  // per event: the byte of the dump its qword starts at
  // Register writes to an address no GS register has (gs_registers.hpp; e.g. A+D to 0x7F): PCSX2's
  // GSState gives them a null handler; counted here, with the first one's address and dump byte.
  std::size_t unused_writes = 0;
  std::uint8_t first_unused_address = 0;
  std::uint64_t first_unused_offset = 0;
};
std::vector<path_stream> decode_paths(const gs_dump& d);

// Compression, as PCSX2 writes it: the whole file as one xz (LZMA2, CRC64) or zstd stream.
enum class compression { none, xz, zstd };
// By extension, compared case-insensitively (PCSX2 GSDumpFile::OpenGSDump: StringUtil::EndsWithNoCase):
// .xz, .zst, else none.
compression compression_for(const std::filesystem::path& file);
std::vector<std::uint8_t> compress(std::span<const std::uint8_t> raw, compression c);
// Recognises the xz (FD 37 7A 58 5A 00) and zstd (28 B5 2F FD) magic numbers; anything else is raw.
std::vector<std::uint8_t> decompress(std::span<const std::uint8_t> file);

gs_dump load_dump(const std::filesystem::path& file);
// Writes atomically (temporary file + rename), compressed as the extension says.
void save_dump(const std::filesystem::path& file, const gs_dump& d);

}  // namespace gs::dump
