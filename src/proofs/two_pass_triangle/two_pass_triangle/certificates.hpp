// two_pass_triangle/certificates.hpp — the wrapping certificates, kept in certificates.csv beside this
// folder's README and compiled in by CMake (cmake/embed_text.cmake): the program reads no file.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "two_pass_triangle/two_pass_triangle.hpp"

namespace gsdot3::proofs::two_pass::triangle {

// One row of certificates.csv: the case, the options it is a certificate under (space-separated
// name=value settings of gs::option_catalogue(), the options it does not name taking any value; "-"
// for none) and its provenance (the tool and command, or the reasoning, that produced it).
struct certificate {
  triangle_case at;
  std::string options, provenance;
};

// The CSV's rows after its header line s,iX,iY,l0_x..l2_z,x0,y0,x1,y1,x2,y2,px,py,options,provenance
// (provenance is the rest of the line and may hold commas). Throws std::invalid_argument naming the
// line on a wrong header, a missing or non-integer field, or an empty provenance.
std::vector<certificate> parse_certificates(std::string_view csv);

// The embedded certificates.csv, parsed on first use (a malformed row stops the program there).
std::span<const certificate> certificate_rows();

}  // namespace gsdot3::proofs::two_pass::triangle
