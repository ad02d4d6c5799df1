// pipeline/scratch.hpp — storage a frame needs only while it is drawn (the value path's frame and Z
// buffers, the memory path's local memory, a band's fragments and runs), kept for the next frame.
// Allocated afresh per frame it cost more than the drawing: glibc hands blocks of this size back to
// the system when they are freed, so the next frame's first write to each 4 KiB page is a page fault
// (perf on an AMD EPYC virtual machine, 2026-12-07: page faults and the zeroing memset were 45 % of a
// four-pass frame's time). A pool per element type keeps released vectors, up to `kept_bytes` in all;
// a taken vector comes back as it was given, size and elements, the smallest that holds `need` if any.
// So a resize to the size it had costs nothing (a frame's buffers were zeroed twice a frame, serially
// by the resize and by the bands): whoever takes one sets what it reads (clear, assign, or writes after
// a resize).
#pragma once

#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace gsdot3::pipeline::detail {

template <class T>
class scratch {
 public:
  static constexpr std::size_t kept_bytes = std::size_t{256} << 20;

  explicit scratch(std::size_t need = 0) : v_(take(need)) {}
  scratch(const scratch&) = delete;
  scratch& operator=(const scratch&) = delete;
  ~scratch() { give(std::move(v_)); }
  std::vector<T>& operator*() noexcept { return v_; }
  std::vector<T>* operator->() noexcept { return &v_; }

 private:
  struct pool {
    std::mutex m;
    std::vector<std::vector<T>> free;
    std::size_t bytes = 0;
  };
  static pool& shared() {
    static pool p;
    return p;
  }
  static std::size_t bytes_of(const std::vector<T>& v) noexcept { return v.capacity() * sizeof(T); }
  static std::vector<T> take(std::size_t need) {
    pool& p = shared();
    const std::lock_guard lock(p.m);
    if (p.free.empty()) return {};
    std::size_t best = 0;  // the smallest that holds `need`, else the largest
    for (std::size_t i = 1; i < p.free.size(); ++i) {
      const std::size_t c = p.free[i].capacity(), b = p.free[best].capacity();
      best = (c >= need && (b < need || c < b)) || (b < need && c > b) ? i : best;
    }
    std::vector<T> v = std::move(p.free[best]);
    p.free.erase(p.free.begin() + static_cast<std::ptrdiff_t>(best));
    p.bytes -= bytes_of(v);
    return v;
  }
  static void give(std::vector<T>&& v) noexcept {
    pool& p = shared();
    const std::lock_guard lock(p.m);
    if (v.capacity() == 0 || p.bytes + bytes_of(v) > kept_bytes) return;  // freed with v
    try {
      p.free.push_back(std::move(v));
      p.bytes += bytes_of(p.free.back());
    } catch (...) {  // no room to keep it: freed as before
    }
  }

  std::vector<T> v_;
};

}  // namespace gsdot3::pipeline::detail
