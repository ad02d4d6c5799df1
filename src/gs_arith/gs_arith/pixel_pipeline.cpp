#include "gs_arith/pixel_pipeline.hpp"

#include <cstdio>

namespace gs {
namespace {

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", static_cast<unsigned>(v));
  return buf;
}

std::string wide(const rgb_wide& w) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "r=%d g=%d b=%d", static_cast<int>(w.r.value()), static_cast<int>(w.g.value()),
                static_cast<int>(w.b.value()));
  return buf;
}

std::string line(const char* stage, const std::string& value) { return std::string(stage) + value + "\n"; }

}  // namespace

std::string format_trace(const pixel_trace& t) {
  std::string s;
  s += line("tfx      ", hex32(t.tfx_out.to_u32()) + "  (Cs/As after the texture function)");
  s += line("atest    ", std::string("rgb=") + (t.test.rgb ? "1" : "0") + " a=" + (t.test.a ? "1" : "0") +
                             " z=" + (t.test.z ? "1" : "0") + "  (written channels)");
  s += line("cd       ", hex32(t.cd.to_u32()) + "  (Cd/Ad as the blender reads the frame buffer)");
  s += line("blend    ", wide(t.blend) + (t.blended ? "  (blended)" : "  (not blended: Cs passes)"));
  s += line("dither   ", wide(t.dithered));
  s += line("colclamp ", hex32(t.clamped.to_u32()));
  s += line("fba      ", hex32(t.fba.to_u32()));
  s += line("pack     ", hex32(t.packed));
  s += line("keep     ", hex32(t.keep) + "  (FBMSK and alpha-test keep mask)");
  s += line("out      ", hex32(t.out));
  return s;
}

}  // namespace gs
