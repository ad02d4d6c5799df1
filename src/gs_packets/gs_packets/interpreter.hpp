// gs_packets/interpreter.hpp — applies a GS dump's GIF events to a modelled local memory: register
// writes are kept, host -> local IMAGE transfers go through gs_memory's host_to_local. Everything the
// model does not cover (drawing primitives, local -> host / local -> local transfers, the display
// registers) is reported by name with the dump byte offset instead of being drawn.
//
// Transfer rule (GS User's Manual section 4; PCSX2 `GSState::Write` / `GIFRegHandlerTRXDIR`): writing
// TRXDIR starts a transfer with the current BITBLTBUF, TRXPOS and TRXREG; the following IMAGE data
// fills the RRW × RRH rectangle; data past the rectangle's last pixel in its last qword is ignored.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/dump.hpp"

namespace gs::packets {

struct unmodelled {
  std::string what;
  std::uint64_t offset = 0;  // byte in the dump
  friend bool operator==(const unmodelled&, const unmodelled&) = default;
};

struct completed_transfer {
  mem::bitbltbuf_reg bitbltbuf;
  mem::trxpos_reg trxpos;
  mem::trxreg_reg trxreg;
  std::uint64_t offset = 0;
};

class interpreter {
 public:
  explicit interpreter(mem::local_memory& m) : mem_(m) {}

  // The memory and registers of a version-8 state blob (other versions: memory left as it is, and
  // reported).
  void load_state(std::span<const std::uint8_t> state, std::uint32_t version);
  void apply(const gif_event& e, std::uint64_t offset);
  // Every path's events in dump order (the order of their bytes in the dump).
  void replay(const dump::gs_dump& d);

  std::uint64_t reg(std::uint8_t address) const noexcept { return regs_[address]; }
  const std::vector<unmodelled>& unmodelled_features() const noexcept { return unmodelled_; }
  const std::vector<completed_transfer>& transfers() const noexcept { return done_; }

 private:
  void start_transfer(std::uint64_t offset);
  void finish_transfer();

  mem::local_memory& mem_;
  std::array<std::uint64_t, 256> regs_{};
  std::vector<unmodelled> unmodelled_;
  std::vector<completed_transfer> done_;
  bool in_transfer_ = false;
  bool kicked_since_prim_ = false;
  completed_transfer current_{};
  std::uint64_t need_ = 0;
  std::vector<std::uint8_t> data_;
};

}  // namespace gs::packets
