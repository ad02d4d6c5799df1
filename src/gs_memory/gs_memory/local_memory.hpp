// gs_memory/local_memory.hpp — the GS's 4 MiB local memory and pixel read / write for every format.
//
// Reads return the format's value bits right-aligned (PSMCT24/PSMZ24: bits 0-23 of the word, the top
// byte is neither read nor written; PSMT8H: bits 24-31; PSMT4HL: 24-27; PSMT4HH: 28-31; PCSX2
// `pcsx2/GS/GSLocalMemory.h` `ReadPixel*`/`WritePixel*` do the same). A write changes exactly the
// location's bits.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gs_memory/address.hpp"
#include "gs_memory/format.hpp"

namespace gs::mem {

class local_memory {
 public:
  local_memory() : words_(memory_bytes / 4, 0) {}
  // The same, zeroed, in `storage`'s memory (a caller that keeps its storage between uses), handed
  // back by release().
  explicit local_memory(std::vector<std::uint32_t>&& storage) : words_(std::move(storage)) {
    words_.assign(memory_bytes / 4, 0);
  }
  std::vector<std::uint32_t> release() && noexcept { return std::move(words_); }

  // Held as 32-bit words, byte a = bits 8·(a % 4) .. of word a / 4 (little-endian).
  constexpr std::uint8_t byte(std::uint32_t a) const noexcept {
    a %= memory_bytes;
    return static_cast<std::uint8_t>(words_[a / 4] >> (8 * (a % 4)));
  }
  constexpr void set_byte(std::uint32_t a, std::uint8_t v) noexcept {
    a %= memory_bytes;
    const unsigned s = 8 * (a % 4);
    words_[a / 4] = (words_[a / 4] & ~(0xFFu << s)) | (std::uint32_t{v} << s);
  }

  // The value at a location (up to 32 bits, little-endian from at.byte, starting at bit at.bit).
  // Every location locate() gives lies inside one 32-bit word (a unit of 4, 8, 16 or 32 bits starts
  // at a multiple of its size, and the upper formats' bits 24-31 / 24-27 / 28-31 are inside the word),
  // so read and write work on that word: bits 8·(byte % 4) + bit .. of word byte / 4.
  // tests/gs_memory/unit_test.cpp checks both against the byte-by-byte little-endian reading on every
  // location of a page of every format.
  constexpr std::uint32_t read(const location& at) const noexcept {
    const unsigned shift = 8 * (at.byte % 4) + at.bit;
    return static_cast<std::uint32_t>((std::uint64_t{words_[at.byte % memory_bytes / 4]} >> shift) &
                                      ((std::uint64_t{1} << at.bits) - 1));
  }
  constexpr void write(const location& at, std::uint32_t value) noexcept {
    const unsigned shift = 8 * (at.byte % 4) + at.bit;
    const auto mask = static_cast<std::uint32_t>(((std::uint64_t{1} << at.bits) - 1) << shift);
    std::uint32_t& w = words_[at.byte % memory_bytes / 4];
    w = (w & ~mask) | ((value << shift) & mask);
  }

  constexpr std::uint32_t read_pixel(const buffer& b, std::uint32_t x, std::uint32_t y) const noexcept {
    return read(locate(b, x, y));
  }
  constexpr void write_pixel(const buffer& b, std::uint32_t x, std::uint32_t y, std::uint32_t v) noexcept {
    write(locate(b, x, y), v);
  }

  // The memory as 32-bit words (PSMCT32 pixel at unit address a = words()[a]): the renderer's frame
  // buffers write through this.
  std::uint32_t* words() noexcept { return words_.data(); }
  const std::uint32_t* words() const noexcept { return words_.data(); }

 private:
  std::vector<std::uint32_t> words_;
};

}  // namespace gs::mem
