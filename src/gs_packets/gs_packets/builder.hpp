// gs_packets/builder.hpp — builds a GIF packet stream: A+D register writes, PACKED vertex data,
// REGLIST and IMAGE (host -> local transfer data). Every method appends one or more GIF tags with
// their data; qwords() is the stream the renderer and the dump writer both consume.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gs_packets/gif_tag.hpp"
#include "gs_packets/packed.hpp"

namespace gs::packets {

class packet_builder {
 public:
  static constexpr unsigned max_nloop = 0x7FFF;

  // PACKED, NREG = 1, REGS = {A+D}: one qword per write.
  packet_builder& ad(std::span<const std::pair<std::uint8_t, std::uint64_t>> writes, bool eop = false) {
    std::vector<qword> data;
    for (const auto& [address, value] : writes) data.push_back(packed_ad(address, value));
    return packed(std::nullopt, std::vector<unsigned>{desc::A_D}, data, eop);
  }

  // PACKED with the given descriptors (1..16); data holds NLOOP × descriptors qwords. With prim, PRE = 1
  // and the tag's PRIM field is written to PRIM first.
  packet_builder& packed(std::optional<std::uint32_t> prim, std::span<const unsigned> descriptors,
                         std::span<const qword> data, bool eop = false) {
    gif_tag t = tag_for(gif_flg::PACKED, descriptors, data.size(), eop);
    if (prim) {
      t.PRE = true;
      t.PRIM = fixed::uint<11>::from_wrapped(*prim & 0x7FF);
    }
    q_.push_back(encode(t));
    q_.insert(q_.end(), data.begin(), data.end());
    return *this;
  }

  // REGLIST: values holds NLOOP × descriptors 64-bit register values, two per qword (an odd count is
  // padded with a zero word, as the manual requires).
  packet_builder& reglist(std::span<const unsigned> descriptors, std::span<const std::uint64_t> values,
                          bool eop = false) {
    q_.push_back(encode(tag_for(gif_flg::REGLIST, descriptors, values.size(), eop)));
    for (std::size_t i = 0; i < values.size(); i += 2)
      q_.push_back({values[i], i + 1 < values.size() ? values[i + 1] : 0});
    return *this;
  }

  // IMAGE: the bytes, zero-padded to whole qwords, split into tags of at most 32767 qwords.
  packet_builder& image(std::span<const std::uint8_t> bytes, bool eop = false) {
    const std::size_t n = (bytes.size() + 15) / 16;
    for (std::size_t first = 0; first < n || (n == 0 && first == 0); first += max_nloop) {
      const std::size_t count = std::min<std::size_t>(max_nloop, n - first);
      gif_tag t;
      t.FLG = gif_flg::IMAGE;
      t.NLOOP = fixed::uint<15>::from_wrapped(static_cast<std::uint32_t>(count));
      t.EOP = eop && first + count >= n;
      q_.push_back(encode(t));
      for (std::size_t k = first; k < first + count; ++k) {
        qword w;
        for (std::size_t b = 0; b < 16; ++b) {
          const std::size_t at = 16 * k + b;
          const std::uint64_t v = at < bytes.size() ? bytes[at] : 0;
          (b < 8 ? w.lo : w.hi) |= v << (8 * (b % 8));
        }
        q_.push_back(w);
      }
      if (n == 0) break;
    }
    return *this;
  }

  const std::vector<qword>& qwords() const noexcept { return q_; }

  // The stream as bytes, little-endian (the GIF's memory order).
  std::vector<std::uint8_t> bytes() const {
    std::vector<std::uint8_t> out;
    out.reserve(16 * q_.size());
    for (const qword& w : q_)
      for (const std::uint64_t v : {w.lo, w.hi})
        for (int b = 0; b < 8; ++b) out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
    return out;
  }

 private:
  static gif_tag tag_for(gif_flg flg, std::span<const unsigned> descriptors, std::size_t items, bool eop) {
    if (descriptors.empty() || descriptors.size() > 16)
      throw std::invalid_argument("GIF tag: 1..16 register descriptors");
    if (items % descriptors.size() != 0)
      throw std::invalid_argument("GIF tag: " + std::to_string(items) + " items is not a multiple of NREG " +
                                  std::to_string(descriptors.size()));
    const std::size_t nloop = items / descriptors.size();
    if (nloop > max_nloop) throw std::invalid_argument("GIF tag: NLOOP " + std::to_string(nloop) + " > 32767");
    gif_tag t;
    t.FLG = flg;
    t.EOP = eop;
    t.NLOOP = fixed::uint<15>::from_wrapped(static_cast<std::uint32_t>(nloop));
    t.NREG = fixed::uint<4>::from_wrapped(static_cast<std::uint32_t>(descriptors.size() & 15));
    for (std::size_t i = 0; i < descriptors.size(); ++i) t.REGS[i] = fixed::uint<4>::from_wrapped(descriptors[i] & 15);
    return t;
  }

  std::vector<qword> q_;
};

}  // namespace gs::packets
