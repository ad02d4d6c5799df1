// gs_packets/interpreter.hpp — applies a GS dump's GIF events to a modelled local memory: register
// writes are kept, host -> local IMAGE transfers go through gs_memory's host_to_local (local -> local
// ones through local_to_local when TRXDIR is written), and vertex kicks
// draw through draw.hpp (the rasteriser and gs::pixel_pipeline). The privileged registers (PMODE,
// DISPFB1/2, DISPLAY1/2) follow the dump's register packets, for the displayed frame (display.hpp).
// What the model does not cover is reported by name with the dump byte offset: a primitive the model
// cannot draw stops the replay (unmodelled_error) unless options::skip_unmodelled, which skips it;
// local -> host transfers and state versions it cannot load are listed and passed over.
//
// Vertex queue (GS User's Manual, "Drawing primitives"; PCSX2 `GSState::VertexKick`): XYZ2 / XYZF2 add
// a vertex with the current RGBAQ, ST, UV (and FOG, or XYZF2's F) and kick drawing once the primitive
// has its vertices; XYZ3 / XYZF3 add one without the kick. After a kick TRIANGLE and SPRITE start over,
// TRIANGLE_STRIP keeps the last two vertices, TRIANGLE_FAN the first and the last. A PRIM write empties
// the queue. PRMODECONT.AC = 0 takes the attribute bits (IIP .. FIX) from PRMODE instead of PRIM.
// TEX0_n (and TEX2_n, which rewrites TEX0_n's PSM and CLUT fields) loads the CLUT as CLD says.
//
// Transfer rule (GS User's Manual section 4; PCSX2 `GSState::Write` / `GIFRegHandlerTRXDIR`): writing
// TRXDIR starts a transfer with the current BITBLTBUF, TRXPOS and TRXREG; the following IMAGE data
// fills the RRW × RRH rectangle; data past the rectangle's last pixel in its last qword is ignored.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <vector>

#include "gs_memory/local_memory.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_arith/options.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/draw.hpp"
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

// A primitive the model cannot draw, when options::skip_unmodelled is off: what() is one line
// "byte N: <what the model lacks>".
struct unmodelled_error : std::runtime_error {
  unmodelled_error(const unmodelled& u)
      : std::runtime_error("byte " + std::to_string(u.offset) + ": " + u.what), feature(u) {}
  unmodelled feature;
};

// What an observer (the GS cost model, src/gs_cost) is told as the interpreter walks a dump; every
// hook does nothing by default. primitive: each kicked primitive, before it is drawn (drawn = false when
// check_primitive refused it: skipped, or about to stop the replay), with the registers it draws with and
// its vertices. transfer: a host -> local transfer whose data is complete, or a local -> local copy, with
// the bytes it moved. clut_load: a TEX0 / TEX2 write that loaded the CLUT buffer (`entries` CLUT
// entries). vsync: a vsync packet of the dump, in dump order (replay only).
struct interpreter_observer {
  virtual ~interpreter_observer() = default;
  virtual void primitive(const draw_registers&, std::span<const vertex>, bool /*drawn*/, std::uint64_t /*offset*/) {}
  virtual void transfer(const completed_transfer&, std::uint64_t /*bytes*/, bool /*local_to_local*/) {}
  virtual void clut_load(std::uint32_t /*entries*/, std::uint64_t /*offset*/) {}
  virtual void vsync(std::uint64_t /*offset*/) {}
};

struct interpreter_options {
  model_options model{};
  bool skip_unmodelled = false;              // skip (and list) primitives the model cannot draw instead of stopping
  interpreter_observer* observer = nullptr;  // not owned; told of primitives, transfers, CLUT loads, vsyncs
};

class interpreter {
 public:
  explicit interpreter(mem::local_memory& m, interpreter_options o = {}) : mem_(m), opt_(o) {}

  // The memory and registers of a state blob whose layout state.hpp knows (dump::state_layout; the
  // transfer in progress, tr.*, is not resumed); any other blob: memory left as it is, and reported.
  void load_state(std::span<const std::uint8_t> state, std::uint32_t version);
  void apply(const gif_event& e, std::uint64_t offset);
  // Every path's events in dump order (the order of their bytes in the dump).
  void replay(const dump::gs_dump& d);

  std::uint64_t reg(std::uint8_t address) const noexcept { return regs_[address]; }
  const std::vector<unmodelled>& unmodelled_features() const noexcept { return unmodelled_; }
  const std::vector<completed_transfer>& transfers() const noexcept { return done_; }
  // The 8 KiB privileged registers as the last register packet (or the dump's header block) left them.
  const std::vector<std::uint8_t>& privileged() const noexcept { return privileged_; }
  std::uint64_t primitives_drawn() const noexcept { return drawn_; }
  std::uint64_t primitives_skipped() const noexcept { return skipped_; }
  std::uint64_t pixels_drawn() const noexcept { return pixels_; }

 private:
  void start_transfer(std::uint64_t offset);
  void finish_transfer();
  void vertex_kick(bool draw, bool with_fog, std::uint64_t offset);
  draw_registers drawing_registers() const;
  void tex0_written(unsigned context, std::uint64_t offset);

  mem::local_memory& mem_;
  std::array<std::uint64_t, 256> regs_{};
  std::vector<unmodelled> unmodelled_;
  std::vector<completed_transfer> done_;
  bool in_transfer_ = false;
  interpreter_options opt_;
  std::array<vertex, 3> queue_{};
  unsigned queued_ = 0;
  clut_unit clut_;
  // The texture page buffer of the current run of primitives (draw_primitive): emptied by TEXFLUSH
  // and by any write that changes a register other than the vertex registers.
  std::optional<mem::texture_page_buffer> texture_;
  std::vector<std::uint8_t> privileged_ = std::vector<std::uint8_t>(8192, 0);
  std::uint64_t drawn_ = 0, skipped_ = 0, pixels_ = 0;
  completed_transfer current_{};
  std::uint64_t need_ = 0;
  std::vector<std::uint8_t> data_;
};

}  // namespace gs::packets
