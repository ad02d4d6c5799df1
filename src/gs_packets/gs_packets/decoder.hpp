// gs_packets/decoder.hpp — walks a GIF qword stream into events: each GIF tag, each GS register write
// (address, 64-bit value, qword offset) and each IMAGE data block.
//
// PACKED: every qword goes through its descriptor (packed.hpp); PRE = 1 writes the tag's PRIM first
// (the manual: PRE is honoured only in PACKED mode). REGLIST: 64-bit values, two per qword, descriptor
// d writes register address d for d <= 0xD; A+D (0xE) and NOP (0xF) write nothing there (unconfirmed:
// the manual's REGLIST rules for A+D were not re-read for this; confidence medium). IMAGE: NLOOP qwords of transfer
// data. Malformed input throws packet_error with one line naming the qword (or byte) offset.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "gs_packets/gif_tag.hpp"

namespace gs::packets {

struct packet_error : std::runtime_error {
  packet_error(const std::string& what, std::size_t byte) : std::runtime_error(what), byte_offset(byte) {}
  std::size_t byte_offset;  // where in the stream the fault is
};

struct gif_event {
  enum class kind : std::uint8_t { tag, reg_write, image };
  kind what = kind::tag;
  std::uint32_t offset = 0;  // qword index in the stream (tag: the tag; write: its qword; image: first data qword)
  gif_tag tag{};             // kind::tag
  std::uint8_t address = 0;  // kind::reg_write
  std::uint64_t value = 0;   // kind::reg_write
  std::span<const std::uint8_t> data;  // kind::image: 16 × NLOOP bytes of the input
};

// q0: the Q register before the stream (PCSX2's GSState constructor sets 1.0f; 0x3F800000).
std::vector<gif_event> decode_gif(std::span<const std::uint8_t> bytes, std::uint32_t q0 = 0x3F800000u);

}  // namespace gs::packets
