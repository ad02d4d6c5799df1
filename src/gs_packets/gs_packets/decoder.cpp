#include "gs_packets/decoder.hpp"

#include <string>

#include "gs_packets/packed.hpp"

namespace gs::packets {
namespace {

std::uint64_t le64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int b = 0; b < 8; ++b) v |= std::uint64_t{p[b]} << (8 * b);
  return v;
}

}  // namespace

std::vector<gif_event> decode_gif(std::span<const std::uint8_t> bytes, std::uint32_t q0) {
  if (bytes.size() % 16 != 0)
    throw packet_error("byte " + std::to_string(bytes.size() - bytes.size() % 16) + ": truncated qword (" +
                           std::to_string(bytes.size() % 16) + " of 16 bytes)",
                       bytes.size() - bytes.size() % 16);
  const std::size_t n = bytes.size() / 16;
  auto at = [&](std::size_t i) { return qword{le64(&bytes[16 * i]), le64(&bytes[16 * i + 8])}; };
  std::vector<gif_event> out;
  std::uint32_t q = q0;
  for (std::size_t i = 0; i < n;) {
    const qword raw = at(i);
    const auto tag = decode_gif_tag(raw);
    if (!tag)
      throw packet_error("qword " + std::to_string(i) + ": GIF tag FLG 3 (disabled) is not a known mode", 16 * i);
    const auto off = static_cast<std::uint32_t>(i);
    out.push_back({gif_event::kind::tag, off, *tag, 0, 0, {}});
    const auto nloop = static_cast<std::uint64_t>(tag->NLOOP.value()), nreg = std::uint64_t{tag->registers()};
    const std::uint64_t need = tag->FLG == gif_flg::PACKED    ? nloop * nreg
                               : tag->FLG == gif_flg::REGLIST ? (nloop * nreg + 1) / 2
                                                              : nloop;
    if (need > n - i - 1)
      throw packet_error("qword " + std::to_string(i) + ": GIF tag NLOOP " + std::to_string(nloop) + " needs " +
                             std::to_string(need) + " data qwords, " + std::to_string(n - i - 1) + " left",
                         16 * i);
    ++i;
    if (tag->FLG == gif_flg::PACKED) {
      if (tag->PRE)
        out.push_back({gif_event::kind::reg_write, off, {}, 0x00, static_cast<std::uint64_t>(tag->PRIM.value()), {}});
      for (std::uint64_t k = 0; k < need; ++k, ++i) {
        const packed_write w = unpack(tag->REGS[k % nreg].value(), at(i), q);
        if (!w.none)
          out.push_back({gif_event::kind::reg_write, static_cast<std::uint32_t>(i), {}, w.address, w.value, {}});
      }
    } else if (tag->FLG == gif_flg::REGLIST) {
      for (std::uint64_t k = 0; k < nloop * nreg; ++k) {
        const qword d = at(i + k / 2);
        const unsigned r = tag->REGS[k % nreg].value();
        if (r <= 0xD)
          out.push_back({gif_event::kind::reg_write,
                         static_cast<std::uint32_t>(i + k / 2),
                         {},
                         static_cast<std::uint8_t>(r),
                         k % 2 == 0 ? d.lo : d.hi,
                         {}});
      }
      i += need;
    } else {
      out.push_back(
          {gif_event::kind::image, static_cast<std::uint32_t>(i), {}, 0, 0, bytes.subspan(16 * i, 16 * need)});
      i += need;
    }
  }
  return out;
}

}  // namespace gs::packets
