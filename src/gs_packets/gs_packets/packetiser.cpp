#include "gs_packets/packetiser.hpp"

#include <stdexcept>
#include <string>

#include "gs_packets/gif_tag.hpp"
#include "gs_packets/packed.hpp"

namespace gs::packets {
namespace {

constexpr std::uint64_t nloop_mask = gs::regs::mask(gif_tag_layout::NLOOP),
                        eop_bit = gs::regs::mask(gif_tag_layout::EOP), pre_bit = gs::regs::mask(gif_tag_layout::PRE);

std::uint64_t le64(std::span<const std::uint8_t> b, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= std::uint64_t{b[at + static_cast<std::size_t>(k)]} << (8 * k);
  return v;
}
qword qword_at(std::span<const std::uint8_t> b, std::size_t i) { return {le64(b, 16 * i), le64(b, 16 * i + 8)}; }

void append(std::vector<std::uint8_t>& out, const qword& q) {
  for (const std::uint64_t v : {q.lo, q.hi})
    for (int k = 0; k < 8; ++k) out.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

// PRIM and the vertices written since it: where a primitive ends (see the header).
struct primitive_walk {
  unsigned prim = 0;  // PCSX2's reset state: PRIM = 0 (POINT)
  std::uint64_t vertices = 0;

  void write(unsigned address, std::uint64_t value) {
    if (address == 0x00) {
      prim = static_cast<unsigned>(value & 7);
      vertices = 0;
    } else if (address == 0x04 || address == 0x05 || address == 0x0C || address == 0x0D) {
      ++vertices;
    }
  }
  bool at_boundary() const {
    switch (prim) {
      case 1:
      case 6: return vertices % 2 == 0;               // LINE, SPRITE
      case 2: return vertices == 0 || vertices >= 2;  // LINE_STRIP
      case 3: return vertices % 3 == 0;               // TRIANGLE
      case 4:
      case 5: return vertices == 0 || vertices >= 3;  // TRIANGLE_STRIP, TRIANGLE_FAN
      default: return true;                           // POINT, reserved
    }
  }
};

class packetiser {
 public:
  packetiser(std::span<const std::uint8_t> s, std::size_t max_bytes) : s_(s), max_q_(max_bytes / 16) {}

  std::vector<std::vector<std::uint8_t>> run() {
    const std::size_t n = s_.size() / 16;
    for (std::size_t i = 0; i < n;) i = one_tag(i, n);
    close();
    return std::move(out_);
  }

 private:
  std::size_t one_tag(std::size_t i, std::size_t n) {
    const qword raw = qword_at(s_, i);
    const auto tag = decode_gif_tag(raw);
    if (!tag) throw std::invalid_argument("GIF packets: qword " + std::to_string(i) + ": FLG 3 is not written");
    const std::uint64_t nloop = tag->NLOOP.value(), nreg = tag->registers();
    const auto need = data_qwords(*tag, 0, nloop);
    if (need > n - i - 1)
      throw std::invalid_argument("GIF packets: qword " + std::to_string(i) + ": the tag's data runs past the stream");
    const std::size_t data0 = i + 1;
    if (tag->FLG == gif_flg::PACKED && tag->PRE) walk_.write(0x00, tag->PRIM.value());
    if (nloop == 0) {
      if (used_q() + 1 > max_q_) close();
      last_tag_ = cur_.size();
      append(cur_, {raw.lo & ~eop_bit, raw.hi});
    }
    // A tag that fits in a packet of its own is not cut.
    if (used_q() > 0 && used_q() + 1 + need > max_q_ && 1 + need <= max_q_) close();
    for (std::uint64_t start = 0; start < nloop;) {
      if (used_q() + 2 > max_q_) close();  // room for a tag and one data qword
      const std::uint64_t room = max_q_ - used_q() - 1;
      std::uint64_t end = start;
      primitive_walk at_end = walk_, w = walk_;
      for (std::uint64_t k = start; k < nloop && data_qwords(*tag, start, k + 1) <= room; ++k) {
        loop_writes(*tag, data0, k, nreg, w);
        if (k + 1 == nloop || (cut_allowed(*tag, k + 1) && w.at_boundary())) end = k + 1, at_end = w;
      }
      if (end == start) {
        if (used_q() == 0)
          throw std::invalid_argument("GIF packets: qword " + std::to_string(i) + ": no cut of this tag fits in " +
                                      std::to_string(16 * max_q_) + " bytes");
        close();
        continue;
      }
      qword t = raw;
      t.lo = (t.lo & ~(nloop_mask | eop_bit)) | ((end - start) & nloop_mask);
      if (start > 0) t.lo &= ~pre_bit;  // PRIM was written by the first part
      last_tag_ = cur_.size();
      append(cur_, t);
      const std::size_t from = data0 + data_qwords(*tag, 0, start), count = data_qwords(*tag, start, end);
      cur_.insert(cur_.end(), s_.begin() + static_cast<std::ptrdiff_t>(16 * from),
                  s_.begin() + static_cast<std::ptrdiff_t>(16 * (from + count)));
      walk_ = at_end;
      start = end;
    }
    if (tag->EOP) close();
    return data0 + need;
  }

  // Data qwords of loops [a, b) (REGLIST: cuts keep a × NREG even, so a starts a qword).
  static std::uint64_t data_qwords(const gif_tag& t, std::uint64_t a, std::uint64_t b) {
    const std::uint64_t nreg = t.registers();
    if (t.FLG == gif_flg::PACKED) return (b - a) * nreg;
    if (t.FLG == gif_flg::REGLIST) return ((b - a) * nreg + 1) / 2;
    return b - a;
  }
  static bool cut_allowed(const gif_tag& t, std::uint64_t k) {
    return t.FLG != gif_flg::REGLIST || (k * t.registers()) % 2 == 0;
  }

  // The register writes of loop k that move the primitive walk (PRIM and the vertex registers).
  void loop_writes(const gif_tag& t, std::size_t data0, std::uint64_t k, std::uint64_t nreg, primitive_walk& w) const {
    if (t.FLG == gif_flg::IMAGE) return;
    for (std::uint64_t r = 0; r < nreg; ++r) {
      const unsigned d = t.REGS[r].value();
      if (t.FLG == gif_flg::PACKED) {
        const qword q = qword_at(s_, data0 + k * nreg + r);
        if (d == desc::A_D)
          w.write(gs::regs::decode_as<unsigned>(packed_layout::A_D_ADDR, q.hi), q.lo);
        else if (d <= 0x0D)
          w.write(d, q.lo);
      } else if (d <= 0x0D) {
        const std::uint64_t v = k * nreg + r;
        const qword q = qword_at(s_, data0 + v / 2);
        w.write(d, v % 2 == 0 ? q.lo : q.hi);
      }
    }
  }

  std::size_t used_q() const { return cur_.size() / 16; }
  void close() {
    if (cur_.empty()) return;
    cur_[last_tag_ + 1] |= 0x80;  // EOP: bit 15 of the tag's first word
    out_.push_back(std::move(cur_));
    cur_.clear();
  }

  std::span<const std::uint8_t> s_;
  std::uint64_t max_q_;
  primitive_walk walk_;
  std::vector<std::uint8_t> cur_;
  std::size_t last_tag_ = 0;
  std::vector<std::vector<std::uint8_t>> out_;
};

}  // namespace

std::vector<std::vector<std::uint8_t>> split_gif_packets(std::span<const std::uint8_t> stream, std::size_t max_bytes) {
  if (max_bytes < 32) throw std::invalid_argument("GIF packets: a packet bound under 32 bytes holds no tag with data");
  if (stream.size() % 16 != 0) throw std::invalid_argument("GIF packets: the stream is not whole qwords");
  return packetiser(stream, max_bytes).run();
}

}  // namespace gs::packets
