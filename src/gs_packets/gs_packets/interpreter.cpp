#include "gs_packets/interpreter.hpp"

#include <algorithm>
#include <tuple>

#include "gs_arith/registers.hpp"
#include "gs_memory/transfer.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/state.hpp"
#include "gs_regs/drawing.hpp"

namespace gs::packets {
namespace {

// The vertices each PRIM.PRIM type needs (GS User's Manual; PCSX2 `NumIndicesForPrim`: 1 for the reserved 7).
constexpr unsigned prim_vertices[8] = {1, 2, 2, 3, 3, 3, 2, 1};

// Context register addresses (context 2 = context 1 + 1), gs_registers.hpp.
constexpr std::uint8_t XYOFFSET_1 = 0x18, TEX0_1 = 0x06, TEX1_1 = 0x14, TEX2_1 = 0x16, CLAMP_1 = 0x08, SCISSOR_1 = 0x40,
                       ALPHA_1 = 0x42, TEST_1 = 0x47, FBA_1 = 0x4A, FRAME_1 = 0x4C, ZBUF_1 = 0x4E, PRMODECONT = 0x1A,
                       PRMODE = 0x1B, TEXCLUT = 0x1C, TEXA = 0x3B, DIMX = 0x44, DTHE = 0x45, COLCLAMP = 0x46,
                       PABE = 0x49, SCANMSK = 0x22;
namespace R = gs::regs;
constexpr std::uint64_t tex2_mask = R::mask(R::TEX2::fields);  // the TEX0 fields a TEX2 write replaces

}  // namespace

draw_registers interpreter::drawing_registers() const {
  const std::uint64_t prim = regs_[reg::PRIM];
  draw_registers r;
  r.PRIM = R::decode(R::PRMODECONT::AC, regs_[PRMODECONT]) != 0
               ? prim
               : (prim & R::mask(R::PRIM::PRIM)) | (regs_[PRMODE] & R::mask(R::PRMODE::fields));
  const auto c = R::decode_as<unsigned>(R::PRIM::CTXT, r.PRIM);
  r.context = c + 1;
  r.XYOFFSET = regs_[XYOFFSET_1 + c];
  r.TEX0 = regs_[TEX0_1 + c];
  r.TEX1 = regs_[TEX1_1 + c];
  r.CLAMP = regs_[CLAMP_1 + c];
  r.SCISSOR = regs_[SCISSOR_1 + c];
  r.ALPHA = regs_[ALPHA_1 + c];
  r.TEST = regs_[TEST_1 + c];
  r.FBA = regs_[FBA_1 + c];
  r.FRAME = regs_[FRAME_1 + c];
  r.ZBUF = regs_[ZBUF_1 + c];
  r.TEXA = regs_[TEXA];
  r.DIMX = regs_[DIMX];
  r.DTHE = regs_[DTHE];
  r.COLCLAMP = regs_[COLCLAMP];
  r.PABE = regs_[PABE];
  r.SCANMSK = regs_[SCANMSK];
  return r;
}

// TEXCLUT (its fields; the bits outside them dropped) is what CSM2 loads read.
// A CLUT load that cannot be modelled leaves its message until a later load succeeds; a TEX0 that
// loads nothing (CLD = 0, CLD 4 / 5 with an unchanged CBP, a non-indexed PSM) keeps it. CLD 4 / 5 load
// exactly when they change CBP0 / CBP1 (gs_memory/clut_load.hpp).
void interpreter::tex0_written(unsigned context, std::uint64_t offset) {
  try {
    const tex0_reg t = decode_tex0(regs_[TEX0_1 + context]);
    const mem::clut_state before = clut_.state;
    clut_.state =
        mem::load_clut(mem_, t, clut_.state, mem::decode_texclut(regs_[TEXCLUT] & R::mask(R::TEXCLUT::fields)));
    const unsigned cld = static_cast<unsigned>(t.CLD.value());
    const bool loaded =
        mem::is_indexed(t.PSM) && ((cld >= 1 && cld <= 3) || (cld == 4 && clut_.state.CBP0 != before.CBP0) ||
                                   (cld == 5 && clut_.state.CBP1 != before.CBP1));
    if (loaded) {
      clut_.load_error.clear();
      const std::uint32_t entries = mem::value_bits(t.PSM) == 8 ? 256u : 16u;  // PSMT8(H): 256; PSMT4(HL, HH): 16
      if (opt_.observer != nullptr) opt_.observer->clut_load(entries, offset);
    }
  } catch (const std::invalid_argument& e) {  // register_error too
    clut_.load_error = std::string(e.what()) + " (TEX0 written at byte " + std::to_string(offset) + ")";
  }
}

void interpreter::vertex_kick(bool draw, bool with_fog, std::uint64_t offset) {
  const std::uint64_t xyz = regs_[draw ? (with_fog ? reg::XYZF2 : reg::XYZ2) : (with_fog ? reg::XYZF3 : reg::XYZ3)];
  const std::uint64_t rgbaq = regs_[reg::RGBAQ], st = regs_[reg::ST], uv = regs_[reg::UV];
  vertex v;
  v.X = R::decode_as<std::uint16_t>(R::XYZ2::X, xyz);  // XYZF2's X and Y are XYZ2's
  v.Y = R::decode_as<std::uint16_t>(R::XYZ2::Y, xyz);
  v.Z = with_fog ? R::decode_as<std::uint32_t>(R::XYZF2::Z, xyz) : R::decode_as<std::uint32_t>(R::XYZ2::Z, xyz);
  v.F =
      with_fog ? R::decode_as<std::uint8_t>(R::XYZF2::F, xyz) : R::decode_as<std::uint8_t>(R::FOG::F, regs_[reg::FOG]);
  v.colour = rgba8::from_u32(static_cast<std::uint32_t>(rgbaq));  // RGBAQ's R, G, B, A: rgba8's own order
  v.Q = R::decode_as<std::uint32_t>(R::RGBAQ::Q, rgbaq);
  v.S = R::decode_as<std::uint32_t>(R::ST::S, st);
  v.T = R::decode_as<std::uint32_t>(R::ST::T, st);
  v.U = R::decode_as<std::uint16_t>(R::UV::U, uv);
  v.V = R::decode_as<std::uint16_t>(R::UV::V, uv);
  const auto type = R::decode_as<unsigned>(R::PRIM::PRIM, regs_[reg::PRIM]);
  const unsigned need = prim_vertices[type];
  if (queued_ >= need) queued_ = 0;
  queue_[queued_++] = v;
  if (queued_ < need) return;
  if (draw) {
    const draw_registers r = drawing_registers();
    const std::span<const vertex> vs(queue_.data(), need);
    const std::string why = check_primitive(r, clut_, vs);
    if (opt_.observer != nullptr) opt_.observer->primitive(r, vs, why.empty(), offset);
    if (!why.empty()) {
      const unmodelled u{std::string(prim_names[type]) + ": " + why, offset};
      unmodelled_.push_back(u);
      if (!opt_.skip_unmodelled) throw unmodelled_error(u);
      ++skipped_;
    } else {
      pixels_ += draw_primitive(mem_, r, clut_, vs, opt_.model, texture_);
      ++drawn_;
    }
  }
  switch (type) {
    case 2: queue_[0] = queue_[1], queued_ = 1; break;                         // LINE_STRIP
    case 4: queue_[0] = queue_[1], queue_[1] = queue_[2], queued_ = 2; break;  // TRIANGLE_STRIP
    case 5: queue_[1] = queue_[2], queued_ = 2; break;                         // TRIANGLE_FAN
    default: queued_ = 0; break;
  }
}

void interpreter::load_state(std::span<const std::uint8_t> state, std::uint32_t version) {
  const auto layout = dump::state_layout(version, state.size());
  if (!layout) {
    unmodelled_.push_back({"state version " + std::to_string(version) + " of " + std::to_string(state.size()) +
                               " bytes: layout not known, registers and memory not loaded",
                           0});
    return;
  }
  const std::uint32_t memory = dump::find_field(*layout, "memory")->offset;
  for (std::uint32_t i = 0; i < dump::memory_bytes; ++i) mem_.set_byte(i, state[memory + i]);
  for (const auto& f : *layout)
    if (const auto a = gs_register_address(f.name)) regs_[*a] = dump::state_get(state, f);
}

void interpreter::start_transfer(std::uint64_t offset) {
  if (in_transfer_) unmodelled_.push_back({"TRXDIR written before the previous transfer's data was complete", offset});
  in_transfer_ = false;
  try {
    const auto dir = mem::decode_trxdir(regs_[reg::TRXDIR]);
    if (dir.XDIR == mem::xdir::deactivated) return;
    current_ = {mem::decode_bitbltbuf(regs_[reg::BITBLTBUF]), mem::decode_trxpos(regs_[reg::TRXPOS]),
                mem::decode_trxreg(regs_[reg::TRXREG]), offset};
    if (dir.XDIR == mem::xdir::local_to_host) {
      unmodelled_.push_back({"TRXDIR.XDIR = 1 (local -> host transfer)", offset});
      return;
    }
    if (dir.XDIR == mem::xdir::local_to_local) {  // runs when TRXDIR is written (PCSX2 `GSState::Move`)
      mem::local_to_local(mem_, current_.bitbltbuf, current_.trxpos, current_.trxreg, dir);
      done_.push_back(current_);
      if (opt_.observer != nullptr) {
        const auto w = static_cast<std::uint32_t>(current_.trxreg.RRW.value());
        const auto h = static_cast<std::uint32_t>(current_.trxreg.RRH.value());
        opt_.observer->transfer(current_, mem::transfer_bytes(current_.bitbltbuf.SPSM, w, h), true);
      }
      return;
    }
  } catch (const register_error& e) {
    unmodelled_.push_back({std::string("transfer registers: ") + e.what(), offset});
    return;
  } catch (const std::invalid_argument& e) {  // a local -> local copy gs_memory does not model
    unmodelled_.push_back({e.what(), offset});
    return;
  }
  need_ = mem::transfer_bytes(current_.bitbltbuf.DPSM, static_cast<std::uint32_t>(current_.trxreg.RRW.value()),
                              static_cast<std::uint32_t>(current_.trxreg.RRH.value()));
  data_.clear();
  in_transfer_ = need_ > 0;
}

void interpreter::finish_transfer() {
  data_.resize(need_);
  try {
    mem::host_to_local(mem_, current_.bitbltbuf, current_.trxpos, current_.trxreg, mem::trxdir_reg{}, data_);
    done_.push_back(current_);
    if (opt_.observer != nullptr) opt_.observer->transfer(current_, need_, false);
  } catch (const std::invalid_argument& e) { unmodelled_.push_back({e.what(), current_.offset}); }
  in_transfer_ = false;
}

void interpreter::apply(const gif_event& e, std::uint64_t offset) {
  if (e.what == gif_event::kind::tag) return;
  if (e.what == gif_event::kind::image) {
    if (!in_transfer_) {
      unmodelled_.push_back({"IMAGE data without an active host -> local transfer (ignored)", offset});
      return;
    }
    const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(e.data.size(), need_ - data_.size()));
    data_.insert(data_.end(), e.data.begin(), e.data.begin() + static_cast<std::ptrdiff_t>(take));
    if (data_.size() == need_) finish_transfer();
    return;
  }
  if (e.address == TEX2_1 || e.address == TEX2_1 + 1) {
    const unsigned c = e.address - TEX2_1;
    regs_[TEX0_1 + c] = (regs_[TEX0_1 + c] & ~tex2_mask) | (e.value & tex2_mask);
  }
  const bool vertex_register = e.address == reg::RGBAQ || e.address == reg::ST || e.address == reg::UV ||
                               e.address == reg::FOG || e.address == reg::XYZ2 || e.address == reg::XYZF2 ||
                               e.address == reg::XYZ3 || e.address == reg::XYZF3;
  if (e.address == reg::TEXFLUSH || (!vertex_register && regs_[e.address] != e.value)) texture_.reset();
  regs_[e.address] = e.value;
  switch (e.address) {
    case reg::TRXDIR: start_transfer(offset); break;
    case reg::PRIM: queued_ = 0; break;
    case reg::XYZ2: vertex_kick(true, false, offset); break;
    case reg::XYZF2: vertex_kick(true, true, offset); break;
    case reg::XYZ3: vertex_kick(false, false, offset); break;
    case reg::XYZF3: vertex_kick(false, true, offset); break;
    case TEX0_1:
    case TEX0_1 + 1: tex0_written(e.address - TEX0_1, offset); break;
    case TEX2_1:
    case TEX2_1 + 1: tex0_written(e.address - TEX2_1, offset); break;
    default: break;
  }
}

void interpreter::replay(const dump::gs_dump& d) {
  load_state(d.state, d.state_version);
  privileged_ = d.privileged;
  const auto paths = dump::decode_paths(d);
  // (dump byte, path or registers_packet, event or packet index)
  constexpr unsigned registers_packet = 255;
  std::vector<std::tuple<std::uint64_t, unsigned, std::size_t>> order;
  for (unsigned p = 0; p < paths.size(); ++p)
    for (std::size_t i = 0; i < paths[p].events.size(); ++i) order.emplace_back(paths[p].file_offsets[i], p, i);
  constexpr unsigned vsync_packet = 254;
  for (std::size_t i = 0; i < d.packets.size(); ++i) {
    if (d.packets[i].type == dump::packet_type::registers) order.emplace_back(d.packets[i].offset, registers_packet, i);
    if (d.packets[i].type == dump::packet_type::vsync && opt_.observer != nullptr)
      order.emplace_back(d.packets[i].offset, vsync_packet, i);
  }
  std::stable_sort(order.begin(), order.end());
  for (const auto& [at, p, i] : order) {
    if (p == registers_packet) {
      if (d.packets[i].data.size() == privileged_.size()) privileged_ = d.packets[i].data;
    } else if (p == vsync_packet) {
      opt_.observer->vsync(at);
    } else {
      apply(paths[p].events[i], at);
    }
  }
  if (in_transfer_)
    unmodelled_.push_back({"the dump ends inside a transfer (" + std::to_string(data_.size()) + " of " +
                               std::to_string(need_) + " bytes)",
                           current_.offset});
}

}  // namespace gs::packets
