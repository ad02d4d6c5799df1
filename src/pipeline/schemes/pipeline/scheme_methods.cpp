// pipeline/scheme_methods.cpp — the one table of the other seeds' methods in the report. A scheme
// adds one row here; its render function lives with the scheme's pipeline glue.
#include <algorithm>

#include "pipeline/scheme_method.hpp"
#include "pipeline/scheme_valve.hpp"
#include "pipeline/scheme_normal_encoding.hpp"
#include "pipeline/scheme_powervr.hpp"

namespace gsdot3::pipeline {

const std::vector<scheme_method>& scheme_methods() {
  static const std::vector<scheme_method> rows = {
      {"rnm", "001 (Green 2007)",
       "RGB8 normal N = 2t − 1, D = saturate(N·B)²/Σ, Σ D_i·saturate(B_i·T) (Listing 1, fp32)", true, render_valve_rnm},
      {"ssbump", "001 (Green 2007)",
       "RGB8 D from normal2ssbump of the same map, Σ t_i·saturate(B_i·T) (Listing 2, fp32)", true, render_valve_ssbump},
      {"enc-xyz", "002 (Pranckevičius 2009)", "normal map stored as XYZ 3×8 unorm, decoded in float (baseline)", false,
       render_enc_xyz},
      {"enc-xy", "002 (Pranckevičius 2009)", "normal map stored as X&Y 2×8, z = sqrt(1 − x² − y²) (#1)", false,
       render_enc_xy},
      {"enc-spheremap", "002 (Pranckevičius 2009)", "normal map stored as sphere map 2×8 (#4; = Lambert, CryEngine 3)",
       false, render_enc_spheremap},
      {"enc-stereographic", "002 (Pranckevičius 2009)", "normal map stored as stereographic 2×8, scale 1.7777 (#7)",
       false, render_enc_stereographic},
      {"enc-octahedral", "002 (Pranckevičius 2009)",
       "normal map stored as octahedral 2×8 unorm, nearest (not in the seed)", false, render_enc_octahedral},
      {"pvr-float", "004 (PowerVR 1999)",
       "16-bit S/R polar texel; K/Q per polygon; K1 + K2 sin S + K3 cos S cos(R − Q) in float (flycast), clamped", true,
       powervr_methods::flat_float},
      {"pvr-fixed8", "004 (PowerVR 1999)",
       "as pvr-float with 8-bit sin/cos tables (precision of the hardware not public)", true,
       powervr_methods::flat_fixed8},
      {"pvr-gouraud", "004 (PowerVR 1999)",
       "as pvr-float with K/Q per vertex, interpolated as flycast does under Gouraud shading", true,
       powervr_methods::gouraud_float},
      {"pvr-pixel", "004 (PowerVR 1999)",
       "as pvr-float with K/Q per pixel (not hardware: isolates the flat-shading error)", true,
       powervr_methods::pixel_float},
      {"pvr-cheap", "004 (PowerVR 1999)",
       "the seed's cheap bump: K1 = 0, K2 = K3 = 255, one Q per object from the screen-space light angle", true,
       powervr_methods::cheap_float},
  };
  return rows;
}

const scheme_method* find_scheme_method(std::string_view name) noexcept {
  const auto& rows = scheme_methods();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const scheme_method& m) { return m.name == name; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::pipeline
