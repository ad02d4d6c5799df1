// pipeline/report_page.hpp — the report as a page (report.html: inline CSS and JavaScript, no
// network, works from file://) that shows the PNGs of its folder and reads the per-pixel data of its
// inspector from report-pixels.js beside it: the folder, not the page alone, is what to copy. The
// page opens on the pictures: the paper's methods' lit frames beside the float reference and an error
// map, with each method's worst pixel (the largest |error| against the reference its report.json
// figures use) in the page's data for the inspector to pin. The page is data-driven: it lists
// whatever methods report.json holds (GS methods, the other seeds' scheme methods), so a method added
// to the report appears on the page without changes here.
//
// report-pixels.js (format 1) assigns one object to `gsdot3_pixels`:
//   {"format": 1, "count": N, "columns": [...], "deflate_base64": "..."}
// The payload is zlib-deflated (RFC 1950), then base64. Inflated, it is the columns one after the
// other, each N values (times `width`) little-endian of its `type` (u8, u16, u32, i32, f32), starting
// at its `offset` in bytes; a column {"name", "const": v} has the same value v at every pixel (an
// array of `width` values for a multi-component column), and
// {"name", "same_as": other} repeats an earlier column. Rows are the covered pixels in raster order
// (column "pixel" = y·width + x). A <script> file because file:// pages may not fetch or XHR.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/prepare.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// A scheme method of the report (scheme_method.hpp) as the page shows it.
struct page_scheme {
  std::string name, seed;
  std::vector<std::vector<float>> dot;  // its dot products [light][pixel], 1/128 units
  bool non_negative = false;            // compared with max(reference, 0), as report.json says
};

struct page_inputs {
  const scene* s = nullptr;
  const prepared_scene* front = nullptr;
  render_options options{};
  std::vector<method> methods;                 // the GS methods of the report, in its order
  const std::vector<frame>* frames = nullptr;  // their renders (the traced re-render is checked against them)
  const reference_frame* reference = nullptr;
  std::vector<page_scheme> schemes;  // the other seeds' methods of the report, in its order
  std::string report_json;           // the text of report.json (the page embeds it)
  double heat_limit = 8.0;           // saturation of the error maps, 1/128 units
  bool pixels = true;                // write report-pixels.js (the inspector's data)
};

struct page_files {
  std::filesystem::path html, pixels;
  std::uintmax_t html_bytes = 0, pixels_bytes = 0;
};

// Writes report-pixels.js and then report.html into dir (each to a temporary name renamed when
// complete). Throws std::runtime_error when a file cannot be written, std::logic_error when a traced
// re-render differs from the report's render.
page_files write_report_page(const std::filesystem::path& dir, const page_inputs& in);

// The claims of the proof catalogue relevant to a method: the GS methods' from a table in
// report_page.cpp, a scheme method's every claim of its seed's section.
std::vector<std::string> claims_for_method(const std::string& name, const std::string& seed);

}  // namespace gsdot3::pipeline
