// gs_memory/texture_buffer.hpp — what a texture fetch sees of local memory written earlier in the
// same draw: the GS's texture page buffer as the model option gs::texture_buffer describes it.
//
// quarter_page: a copy of the 2 KiB that holds the 32×16-pixel quarter of the PSMCT32 page being read
//   (blocks 8q .. 8q + 7 of the page: the quarter's blocks share block-number bits 3 and 4, the top two,
//   so the quarter is contiguous), reloaded from memory when a fetch leaves it;
// page: the same with the whole 8 KiB page; per_fragment: memory as written so far;
// draw_snapshot: memory as it was when the draw began (the snapshot covers [first, first + size)).
// Writes go to memory only. Evidence and confidence: gs_arith/options.hpp (no hardware test).
#pragma once

#include <cstdint>
#include <vector>

#include "gs_arith/options.hpp"
#include "gs_memory/local_memory.hpp"

namespace gs::mem {

class texture_page_buffer {
 public:
  texture_page_buffer(gs::texture_buffer mode, const local_memory& m, std::uint32_t first, std::uint32_t size)
      : mode_(mode), m_(m), first_(first) {
    if (mode_ == gs::texture_buffer::draw_snapshot) {
      copy_.resize(size);
      for (std::uint32_t i = 0; i < size; ++i) copy_[i] = m.byte(first + i);
    }
  }

  std::uint8_t fetch(std::uint32_t a) {
    switch (mode_) {
      case gs::texture_buffer::per_fragment: return m_.byte(a);
      case gs::texture_buffer::draw_snapshot: return copy_[a - first_];
      case gs::texture_buffer::quarter_page: return buffered(a, 2048);
      case gs::texture_buffer::page: return buffered(a, page_bytes);
    }
    return m_.byte(a);
  }
  std::uint32_t loads() const noexcept { return loads_; }

 private:
  std::uint8_t buffered(std::uint32_t a, std::uint32_t size) {
    const std::uint32_t region = a / size;
    if (!valid_ || region != region_) {
      copy_.resize(size);
      for (std::uint32_t i = 0; i < size; ++i) copy_[i] = m_.byte(region * size + i);
      region_ = region;
      valid_ = true;
      ++loads_;
    }
    return copy_[a % size];
  }

  gs::texture_buffer mode_;
  const local_memory& m_;
  std::uint32_t first_;
  std::vector<std::uint8_t> copy_;
  std::uint32_t region_ = 0, loads_ = 0;
  bool valid_ = false;
};

}  // namespace gs::mem
