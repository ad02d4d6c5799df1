#include "gs_packets/interpreter.hpp"

#include <algorithm>
#include <tuple>

#include "gs_arith/registers.hpp"
#include "gs_memory/transfer.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/state.hpp"

namespace gs::packets {
namespace {

// PRIM.PRIM (bits 0-2) names, GS User's Manual.
constexpr const char* prim_names[8] = {"POINT", "LINE", "LINE_STRIP", "TRIANGLE", "TRIANGLE_STRIP", "TRIANGLE_FAN",
                                       "SPRITE", "PRIM 7 (reserved)"};

}  // namespace

void interpreter::load_state(std::span<const std::uint8_t> state, std::uint32_t version) {
  if (version != 8 || state.size() != dump::state_size_v8) {
    unmodelled_.push_back({"state version " + std::to_string(version) + ": registers and memory not loaded", 0});
    return;
  }
  for (std::uint32_t i = 0; i < dump::memory_bytes; ++i) mem_.set_byte(i, state[dump::state_memory_offset_v8 + i]);
  for (const auto& f : dump::state_fields_v8)
    if (const auto a = gs_register_address(f.name)) regs_[*a] = dump::state_get(state, f);
}

void interpreter::start_transfer(std::uint64_t offset) {
  if (in_transfer_) unmodelled_.push_back({"TRXDIR written before the previous transfer's data was complete", offset});
  in_transfer_ = false;
  try {
    const auto dir = mem::decode_trxdir(regs_[reg::TRXDIR]);
    if (dir.XDIR == mem::xdir::deactivated) return;
    if (dir.XDIR != mem::xdir::host_to_local) {
      unmodelled_.push_back({dir.XDIR == mem::xdir::local_to_host ? "TRXDIR.XDIR = 1 (local -> host transfer)"
                                                                  : "TRXDIR.XDIR = 2 (local -> local transfer)",
                             offset});
      return;
    }
    current_ = {mem::decode_bitbltbuf(regs_[reg::BITBLTBUF]), mem::decode_trxpos(regs_[reg::TRXPOS]),
                mem::decode_trxreg(regs_[reg::TRXREG]), offset};
  } catch (const register_error& e) {
    unmodelled_.push_back({std::string("transfer registers: ") + e.what(), offset});
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
  } catch (const std::invalid_argument& e) {
    unmodelled_.push_back({e.what(), current_.offset});
  }
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
  regs_[e.address] = e.value;
  switch (e.address) {
    case reg::TRXDIR: start_transfer(offset); break;
    case reg::PRIM: kicked_since_prim_ = false; break;
    case reg::XYZ2:
    case reg::XYZF2:
      if (!kicked_since_prim_)
        unmodelled_.push_back({std::string("drawing ") + prim_names[regs_[reg::PRIM] & 7] + " (vertex kick through " +
                                   (e.address == reg::XYZ2 ? "XYZ2" : "XYZF2") + "): primitives are not drawn by replay yet",
                               offset});
      kicked_since_prim_ = true;
      break;
    default: break;
  }
}

void interpreter::replay(const dump::gs_dump& d) {
  load_state(d.state, d.state_version);
  const auto paths = dump::decode_paths(d);
  std::vector<std::tuple<std::uint64_t, unsigned, std::size_t>> order;  // (dump byte, path, event)
  for (unsigned p = 0; p < paths.size(); ++p)
    for (std::size_t i = 0; i < paths[p].events.size(); ++i) order.emplace_back(paths[p].file_offsets[i], p, i);
  std::stable_sort(order.begin(), order.end());
  for (const auto& [at, p, i] : order) apply(paths[p].events[i], at);
  if (in_transfer_)
    unmodelled_.push_back({"the dump ends inside a transfer (" + std::to_string(data_.size()) + " of " +
                               std::to_string(need_) + " bytes)",
                           current_.offset});
}

}  // namespace gs::packets
