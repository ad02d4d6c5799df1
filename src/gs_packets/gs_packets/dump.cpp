#include "gs_packets/dump.hpp"

#include <fstream>
#include <iterator>
#include <system_error>

#include "gs_packets/gs_registers.hpp"
#include "gs_packets/state.hpp"

namespace gs::dump {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
}
void put(std::vector<std::uint8_t>& out, std::span<const std::uint8_t> bytes) {
  out.insert(out.end(), bytes.begin(), bytes.end());
}

// Reads the dump front to back; every fault names the byte where it is.
class reader {
 public:
  explicit reader(std::span<const std::uint8_t> b) : b_(b) {}
  std::size_t at() const { return at_; }
  std::size_t left() const { return b_.size() - at_; }
  bool done() const { return at_ == b_.size(); }
  std::span<const std::uint8_t> take(std::size_t n, const std::string& what) {
    if (n > left())
      throw dump_error("byte " + std::to_string(at_) + ": " + what + " of " + std::to_string(n) +
                       " bytes runs past the end of the dump (" + std::to_string(left()) + " left)");
    const auto s = b_.subspan(at_, n);
    at_ += n;
    return s;
  }
  std::uint8_t u8(const std::string& what) { return take(1, what)[0]; }
  std::uint32_t u32(const std::string& what) {
    const auto s = take(4, what);
    return std::uint32_t{s[0]} | (std::uint32_t{s[1]} << 8) | (std::uint32_t{s[2]} << 16) | (std::uint32_t{s[3]} << 24);
  }

 private:
  std::span<const std::uint8_t> b_;
  std::size_t at_ = 0;
};

std::uint32_t le32(std::span<const std::uint8_t> s, std::size_t at) {
  return std::uint32_t{s[at]} | (std::uint32_t{s[at + 1]} << 8) | (std::uint32_t{s[at + 2]} << 16) |
         (std::uint32_t{s[at + 3]} << 24);
}

// GSState::Defrost: "if (version > STATE_VERSION) { Console.Error(\"GS: Savestate version is incompatible.
// Load aborted.\"); return -1; }", STATE_VERSION 9 in the newest GSState.h.
constexpr std::uint32_t pcsx2_state_version_max = 9;

void check_state(gs_dump& d, std::size_t at) {
  if (d.state.size() < 4)
    throw dump_error("byte " + std::to_string(at) + ": state size " + std::to_string(d.state.size()) +
                     " is too small for the state version u32");
  const std::uint32_t blob_version = le32(d.state, 0);
  if (blob_version != d.state_version) {
    d.notices.push_back({"state_version_differs", at,
                         "the header's state_version " + std::to_string(d.state_version) + " differs from the blob's " +
                             std::to_string(blob_version) + "; the blob's is used, as PCSX2's GSState::Defrost does"});
    d.state_version = blob_version;
  }
  if (d.state_version > pcsx2_state_version_max)
    throw dump_error("byte " + std::to_string(at) + ": state version " + std::to_string(d.state_version) +
                     ": GS: Savestate version is incompatible.  Load aborted. (PCSX2's GSState::Defrost loads versions "
                     "0.." +
                     std::to_string(pcsx2_state_version_max) + ")");
  // Versions 8 and 9 are the ones PCSX2 writes now: their size is checked (older blobs are read and,
  // when their size fits their layout, decoded by the interpreter).
  if ((d.state_version == 8 || d.state_version == 9) && !state_layout(d.state_version, d.state.size()))
    throw dump_error("byte " + std::to_string(at) + ": state size " + std::to_string(d.state.size()) +
                     " does not fit the version " + std::to_string(d.state_version) +
                     " layout (PCSX2's GSState::Freeze: " + std::to_string(state_size_v8) + " bytes for version 8, " +
                     std::to_string(state_size_v9) +
                     " for 9; gsdot3's older version 8: " + std::to_string(state_size_gsdot3_v8) + ")");
  if (d.state_version == 8 && d.state.size() == state_size_gsdot3_v8)
    d.notices.push_back({"gsdot3_state_layout", at,
                         "a version-8 state of " + std::to_string(state_size_gsdot3_v8) +
                             " bytes is gsdot3's layout before issue 57 (UV and FOG 8 bytes each, not PCSX2's 4): read "
                             "as such; PCSX2 and parallel-gs would read every field from XYZ on 8 bytes off (write "
                             "the dump again with gsdot3 dump for PCSX2's layout)"});
}

// The body of a packet read, or a notice when the dump ends inside it (PCSX2 drops that last packet).
bool take_body(reader& r, gs_dump& d, std::size_t n, std::uint64_t packet_at, std::span<const std::uint8_t>& body) {
  if (n > r.left()) {
    d.notices.push_back({"truncated_last_packet", packet_at,
                         "the last packet needs " + std::to_string(n) + " bytes, the dump has " +
                             std::to_string(r.left()) + "; dropped, as PCSX2's GSDumpFile::ReadFile does"});
    return false;
  }
  body = r.take(n, "packet");
  return true;
}

}  // namespace

std::vector<std::uint8_t> write_dump(const gs_dump& d) {
  if (d.screenshot.size() != std::uint64_t{d.screenshot_width} * d.screenshot_height * 4)
    throw dump_error("screenshot: " + std::to_string(d.screenshot.size()) + " bytes for " +
                     std::to_string(d.screenshot_width) + "x" + std::to_string(d.screenshot_height) + " RGBA");
  if (d.privileged.size() != privileged_bytes) throw dump_error("privileged registers: need 8192 bytes");
  std::vector<std::uint8_t> out;
  const auto serial_size = static_cast<std::uint32_t>(d.serial.size());
  const auto shot_size = static_cast<std::uint32_t>(d.screenshot.size());
  put32(out, new_layout_marker);
  put32(out, header_bytes + serial_size + shot_size);
  for (const std::uint32_t v : {d.state_version, static_cast<std::uint32_t>(d.state.size()), header_bytes, serial_size,
                                d.crc, d.screenshot_width, d.screenshot_height, header_bytes + serial_size, shot_size})
    put32(out, v);
  out.insert(out.end(), d.serial.begin(), d.serial.end());
  put(out, d.screenshot);
  put(out, d.state);
  put(out, d.privileged);
  for (const packet& p : d.packets) {
    out.push_back(static_cast<std::uint8_t>(p.type));
    switch (p.type) {
      case packet_type::transfer:
        out.push_back(p.path);
        put32(out, static_cast<std::uint32_t>(p.data.size()));
        put(out, p.data);
        break;
      case packet_type::vsync: out.push_back(p.field); break;
      case packet_type::read_fifo2: put32(out, p.size); break;
      case packet_type::registers:
        if (p.data.size() != privileged_bytes) throw dump_error("registers packet: need 8192 bytes");
        put(out, p.data);
        break;
    }
  }
  return out;
}

void assign_offsets(gs_dump& d) {
  // write_dump's order: marker and header size (8), GSDumpHeader, serial, screenshot, state, registers.
  std::uint64_t at = 8 + header_bytes + d.serial.size() + d.screenshot.size() + d.state.size() + d.privileged.size();
  for (packet& p : d.packets) {
    p.offset = at;
    switch (p.type) {
      case packet_type::transfer: at += 1 + 1 + 4 + p.data.size(); break;
      case packet_type::vsync: at += 1 + 1; break;
      case packet_type::read_fifo2: at += 1 + 4; break;
      case packet_type::registers: at += 1 + privileged_bytes; break;
    }
  }
}

gs_dump read_dump(std::span<const std::uint8_t> bytes) {
  reader r(bytes);
  gs_dump d;
  const std::uint32_t first = r.u32("dump header");
  d.new_layout = first == new_layout_marker;
  if (d.new_layout) {
    const std::uint32_t header_size = r.u32("header size");
    const std::size_t header_at = r.at();
    if (header_size < header_bytes)
      throw dump_error("byte 4: header size " + std::to_string(header_size) + " is smaller than GSDumpHeader (36)");
    const auto h = r.take(header_size, "header");
    d.state_version = le32(h, 0);
    const std::uint32_t state_size = le32(h, 4), serial_offset = le32(h, 8), serial_size = le32(h, 12);
    d.crc = le32(h, 16);
    d.screenshot_width = le32(h, 20);
    d.screenshot_height = le32(h, 24);
    const std::uint32_t shot_offset = le32(h, 28), shot_size = le32(h, 32);
    auto inside = [&](std::uint32_t off, std::uint32_t size) { return std::uint64_t{off} + size <= header_size; };
    if (serial_size > 0 && !inside(serial_offset, serial_size))
      throw dump_error("byte " + std::to_string(header_at) + ": serial at " + std::to_string(serial_offset) + " (+" +
                       std::to_string(serial_size) + ") lies outside the header of " + std::to_string(header_size) +
                       " bytes: GSDump header is corrupted. (PCSX2 GSDumpFile::ReadFile)");
    if (serial_size > 0) d.serial.assign(h.begin() + serial_offset, h.begin() + serial_offset + serial_size);
    const std::uint64_t shot_expected = std::uint64_t{d.screenshot_width} * d.screenshot_height * 4;
    if (shot_expected == shot_size && inside(shot_offset, shot_size)) {
      d.screenshot.assign(h.begin() + shot_offset, h.begin() + shot_offset + shot_size);
    } else {
      d.notices.push_back({"screenshot_ignored", header_at + 20,
                           "screenshot " + std::to_string(d.screenshot_width) + "x" +
                               std::to_string(d.screenshot_height) + " with " + std::to_string(shot_size) +
                               " bytes at " + std::to_string(shot_offset) + " (header of " +
                               std::to_string(header_size) +
                               " bytes) is not width x height x 4 within "
                               "the header; ignored, as PCSX2's GSDumpFile::ReadFile does"});
      d.screenshot_width = d.screenshot_height = 0;
    }
    const std::size_t state_at = r.at();
    const auto s = r.take(state_size, "state");
    d.state.assign(s.begin(), s.end());
    check_state(d, state_at);
  } else {
    d.crc = first;
    const std::uint32_t state_size = r.u32("state size");
    const std::size_t state_at = r.at();
    const auto s = r.take(state_size, "state");
    d.state.assign(s.begin(), s.end());
    if (state_size < 4)
      throw dump_error("byte 4: state size " + std::to_string(state_size) + " is too small for the state version u32");
    d.state_version = le32(d.state, 0);
    check_state(d, state_at);
  }
  const auto regs = r.take(privileged_bytes, "privileged registers");
  d.privileged.assign(regs.begin(), regs.end());
  while (!r.done()) {
    packet p;
    p.offset = r.at();
    const std::uint8_t type = r.u8("packet type");
    std::span<const std::uint8_t> body;
    bool skip = false;
    switch (type) {
      case 0: {
        p.type = packet_type::transfer;
        p.path = r.u8("transfer path");
        const std::uint32_t size = r.u32("transfer size");
        if (!take_body(r, d, size, p.offset, body)) return d;
        p.data.assign(body.begin(), body.end());
        if (p.path > 3) {
          d.notices.push_back({"transfer_path_skipped", p.offset,
                               "transfer path " + std::to_string(p.path) + " (0..3) with " + std::to_string(size) +
                                   " bytes; skipped, as PCSX2's GSDumpReplayer does"});
          skip = true;
        }
        break;
      }
      case 1:
        p.type = packet_type::vsync;
        if (!take_body(r, d, 1, p.offset, body)) return d;
        p.field = body[0];
        break;
      case 2:
        p.type = packet_type::read_fifo2;
        if (!take_body(r, d, 4, p.offset, body)) return d;
        p.size = le32(body, 0);
        break;
      case 3:
        p.type = packet_type::registers;
        if (!take_body(r, d, privileged_bytes, p.offset, body)) return d;
        p.data.assign(body.begin(), body.end());
        break;
      default:
        throw dump_error("byte " + std::to_string(p.offset) + ": unknown packet type " + std::to_string(type) +
                         " (0..3)");
    }
    if (!skip) d.packets.push_back(std::move(p));
  }
  return d;
}

std::vector<path_stream> decode_paths(const gs_dump& d) {
  std::vector<path_stream> paths(4);
  std::vector<std::vector<std::pair<std::size_t, const packet*>>> starts(4);  // (stream byte, packet)
  for (std::size_t i = 1; i < d.packets.size(); ++i)
    if (d.packets[i].offset <= d.packets[i - 1].offset)
      throw dump_error("packet " + std::to_string(i) + " at byte " + std::to_string(d.packets[i].offset) +
                       " does not follow packet " + std::to_string(i - 1) + " at byte " +
                       std::to_string(d.packets[i - 1].offset) +
                       ": offsets unset (a dump built in memory needs "
                       "assign_offsets)");
  for (const packet& p : d.packets) {
    if (p.type != packet_type::transfer || p.path > 3) continue;
    starts[p.path].emplace_back(paths[p.path].bytes.size(), &p);
    paths[p.path].bytes.insert(paths[p.path].bytes.end(), p.data.begin(), p.data.end());
  }
  for (unsigned i = 0; i < 4; ++i) {
    try {
      paths[i].events = packets::decode_gif(paths[i].bytes);
    } catch (const packets::packet_error& e) {
      std::size_t k = 0;
      while (k + 1 < starts[i].size() && starts[i][k + 1].first <= e.byte_offset) ++k;
      const auto& [start, pkt] = starts[i][k];
      throw dump_error("byte " + std::to_string(pkt->offset + 6 + (e.byte_offset - start)) + " (path " +
                       std::to_string(i) + " transfer at byte " + std::to_string(pkt->offset) + "): " + e.what());
    }
    std::size_t k = 0;
    for (const auto& e : paths[i].events) {
      const std::size_t at = 16 * std::size_t{e.offset};
      while (k + 1 < starts[i].size() && starts[i][k + 1].first <= at) ++k;
      paths[i].file_offsets.push_back(starts[i][k].second->offset + 6 + (at - starts[i][k].first));
      if (e.what == packets::gif_event::kind::reg_write && !packets::gs_register_name_of(e.address)) {
        if (paths[i].unused_writes++ == 0) {
          paths[i].first_unused_address = e.address;
          paths[i].first_unused_offset = paths[i].file_offsets.back();
        }
      }
    }
  }
  return paths;
}

std::string describe(const notice& n) { return "byte " + std::to_string(n.offset) + ": " + n.name + ": " + n.text; }

gs_dump load_dump(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw dump_error(file.string() + ": cannot open");
  std::vector<std::uint8_t> raw;
  try {  // libstdc++'s filebuf throws on a read error (a directory opens, then reads EISDIR)
    raw.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const std::ios_base::failure& e) {
    throw dump_error(file.string() + ": cannot read (" + e.code().message() + ")");
  }
  try {
    return read_dump(decompress(raw));
  } catch (const dump_error& e) { throw dump_error(file.string() + ": " + e.what()); }
}

void save_dump(const std::filesystem::path& file, const gs_dump& d) {
  const std::vector<std::uint8_t> bytes = compress(write_dump(d), compression_for(file));
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw dump_error(file.string() + ": cannot write");
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw dump_error(file.string() + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) throw dump_error(file.string() + ": " + ec.message());
}

}  // namespace gs::dump
