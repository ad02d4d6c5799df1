#include "pipeline/texture_stream.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "gs_packets/decoder.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/interpreter.hpp"

namespace gsdot3::pipeline {

namespace {

constexpr std::uint32_t memory_pages = gs::mem::memory_blocks / 32;  // 512

gs::mem::extent page_of(gs::mem::psm p) { return gs::mem::page_size(gs::mem::layout_of(p)); }
// Bytes a texel takes in stream_texture::texels: one for the 4- and 8-bit indices, four for PSMCT32.
int bytes_per_texel(gs::mem::psm p) { return std::max(1u, gs::mem::value_bits(p) / 8); }

// The pages cell (c, r) takes at page stride w, relative to the page of TBP0, and the shortest run of
// pages (cyclic, the memory wraps) holding all of them: its first position and its length. Nothing
// when two cells share a page.
struct arrangement {
  std::vector<std::uint32_t> at;  // per cell
  std::uint32_t first = 0, length = 0;
};
std::optional<arrangement> arrange(const std::vector<std::array<int, 2>>& cells, std::uint32_t w) {
  arrangement a;
  for (const auto& [c, r] : cells)
    a.at.push_back((static_cast<std::uint32_t>(c) + static_cast<std::uint32_t>(r) * w) % memory_pages);
  std::vector<std::uint32_t> sorted = a.at;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
  std::uint32_t gap = sorted.front() + memory_pages - sorted.back();  // the gap across the wrap
  a.first = sorted.front();
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] - sorted[i - 1] > gap) gap = sorted[i] - sorted[i - 1], a.first = sorted[i];
  a.length = memory_pages - gap + 1;
  return a;
}

// TBW of page stride w (pages of `p` per row of pages), and the largest stride TBW's 6 bits allow.
std::uint32_t tbw(gs::mem::psm p, std::uint32_t w) { return w * page_of(p).w / 64; }
std::uint32_t widest(gs::mem::psm p) { return 63 * 64 / page_of(p).w; }
// The strides a piece may use: the texture's own row of pages first, then 1, 2, ... up to widest.
std::vector<std::uint32_t> strides(const stream_texture& t) {
  const std::uint32_t own =
      std::min(widest(t.PSM), (static_cast<std::uint32_t>(t.width) + page_of(t.PSM).w - 1) / page_of(t.PSM).w);
  std::vector<std::uint32_t> s{own};
  for (std::uint32_t w = 1; w <= widest(t.PSM); ++w)
    if (w != own) s.push_back(w);
  return s;
}

}  // namespace

bool may_cover(const prepared_triangle& t, const scissor& r) {
  const auto& v = t.setup.v;
  const int x0 = ceil_124(std::min({v[0].x, v[1].x, v[2].x})) - 1,
            x1 = ceil_124(std::max({v[0].x, v[1].x, v[2].x})) + 1;
  const int y0 = ceil_124(std::min({v[0].y, v[1].y, v[2].y})) - 1,
            y1 = ceil_124(std::max({v[0].y, v[1].y, v[2].y})) + 1;
  return x0 < r.x1 && r.x0 < x1 && y0 < r.y1 && r.y0 < y1;
}

void host_transfer(gs::packets::packet_builder& out, const gs::mem::buffer& b, int w, int h,
                   std::span<const std::uint8_t> data) {
  namespace reg = gs::packets::reg;
  gs::mem::bitbltbuf_reg blt;
  blt.DBP = b.BP;
  blt.DBW = b.BW;
  blt.DPSM = b.PSM;
  const gs::mem::trxreg_reg size{fixed::uint<12>::from_wrapped(w), fixed::uint<12>::from_wrapped(h)};
  const std::pair<std::uint8_t, std::uint64_t> writes[] = {{reg::BITBLTBUF, gs::mem::encode(blt)},
                                                           {reg::TRXPOS, gs::mem::encode(gs::mem::trxpos_reg{})},
                                                           {reg::TRXREG, gs::mem::encode(size)},
                                                           {reg::TRXDIR, gs::mem::encode(gs::mem::trxdir_reg{})}};
  out.ad(writes);
  if (gs::mem::value_bits(b.PSM) != 4) {
    out.image(data);
    return;
  }
  if (data.size() % 2 != 0) throw std::invalid_argument("host_transfer: an odd number of 4-bit texels");
  std::vector<std::uint8_t> packed(data.size() / 2);
  for (std::size_t i = 0; i < packed.size(); ++i)
    packed[i] = static_cast<std::uint8_t>((data[2 * i] & 0xFu) | (data[2 * i + 1] & 0xFu) << 4);
  out.image(packed);
}

void interpret(gs::mem::local_memory& m, const gs::packets::packet_builder& b) {
  const std::vector<std::uint8_t> bytes = b.bytes();
  gs::packets::interpreter gs(m);
  for (const gs::packets::gif_event& e : gs::packets::decode_gif(bytes)) gs.apply(e, 16 * std::uint64_t{e.offset});
  if (!gs.unmodelled_features().empty())
    throw std::logic_error("memory path upload: " + gs.unmodelled_features().front().what);
}

texture_streamer::texture_streamer(const prepared_scene& ps, const gs::model_options& model, gs::bilinear_mode filter,
                                   scissor area, std::uint32_t first_page, std::uint32_t end_page)
    : ps_(ps),
      filter_(filter),
      rows_only_(model.setup == gs::gouraud_setup::pcsx2_rows_4 || model.setup == gs::gouraud_setup::pcsx2_rows_8),
      area_(area),
      first_(first_page),
      end_(end_page) {
  for (const prepared_triangle& t : ps.triangles)
    uv_.push_back(gs::setup_attributes(t.setup, {}, t.uv16, xy_offset_pixels, xy_offset_pixels, model.setup,
                                       gs::uv_rule_of(model)));
}

std::vector<std::array<int, 2>> texture_streamer::cells_in(const stream_texture& t, const scissor& a,
                                                           const std::vector<std::uint32_t>& tris) const {
  const gs::mem::extent pg = page_of(t.PSM);
  const int columns = (t.width + static_cast<int>(pg.w) - 1) / static_cast<int>(pg.w);
  const int rows = (t.height + static_cast<int>(pg.h) - 1) / static_cast<int>(pg.h);
  std::vector<bool> needed(static_cast<std::size_t>(columns * rows));
  for (std::uint32_t i : tris) {
    const gs::triangle_attributes& uv = uv_[i];
    rasterise_triangle(ps_.triangles[i].setup, a, [&](int x, int y) {
      // the footprint gs::sample fetches, wrapped as texture_ref::fetch (REPEAT) wraps it
      gs::sample(
          [&](std::int32_t u, std::int32_t v) {
            u &= t.width - 1;
            v &= t.height - 1;
            needed[static_cast<std::size_t>(v / static_cast<int>(pg.h) * columns + u / static_cast<int>(pg.w))] = true;
            return gs::rgba8{};
          },
          uv.u.at(x, y), uv.v.at(x, y), filter_);
    });
  }
  std::vector<std::array<int, 2>> cells;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c)
      if (needed[static_cast<std::size_t>(r * columns + c)]) cells.push_back({c, r});
  return cells;
}

bool texture_streamer::placeable(const stream_texture& t, const std::vector<std::array<int, 2>>& cells) const {
  for (std::uint32_t w : strides(t))
    if (const auto a = arrange(cells, w); a && a->length <= window_pages()) return true;
  return false;
}

// A k-d split of the drawn area: a rectangle whose cells fit the window is a leaf, else its halves
// along the longer side are tried; a rectangle no triangle pixel is in is dropped. Under PCSX2's row
// set-ups (rows_only_, the header's reason 1) the cuts are along y only, and a single row that does
// not fit is split by triangles instead: two pieces over the same row, the first drawing the lower
// half of the triangles that reach it, the second the rest, so each pixel still sees its fragments in
// the pass's triangle order (next_pass keeps such pieces in that order).
void texture_streamer::split(const stream_texture& t, const scissor& a, triangle_range range,
                             const std::vector<std::uint32_t>& tris, std::vector<leaf>& out) {
  std::vector<std::uint32_t> in;
  for (std::uint32_t i : tris)
    if (may_cover(ps_.triangles[i], a)) in.push_back(i);
  std::vector<std::array<int, 2>> cells = cells_in(t, a, in);
  if (cells.empty()) return;
  if (placeable(t, cells)) {
    out.push_back({a, range, std::move(cells)});
    return;
  }
  const bool one_row = a.y1 - a.y0 == 1;
  if (one_row && (rows_only_ ? in.size() == 1 : a.x1 - a.x0 == 1))
    throw texture_does_not_fit(
        "memory path: " +
        (rows_only_ ? "triangle " + std::to_string(in.front()) + " on row " + std::to_string(a.y0) +
                          " (pieces are whole rows under gouraud_setup pcsx2_rows)"
                    : "pixel (" + std::to_string(a.x0) + ", " + std::to_string(a.y0) + ")") +
        " fetches the " + std::to_string(t.width) + "x" + std::to_string(t.height) + " " + t.name + " from " +
        std::to_string(cells.size()) + " pages, more than the " + std::to_string(window_pages()) +
        " pages free beside the frame buffers: use a smaller --size or a smaller normal map");
  if (rows_only_ && one_row) {
    const auto mid = in.begin() + static_cast<std::ptrdiff_t>(in.size() / 2);
    split(t, a, {range.first, *mid}, {in.begin(), mid}, out);
    split(t, a, {*mid, range.end}, {mid, in.end()}, out);
    return;
  }
  scissor lo = a, hi = a;
  if (!rows_only_ && a.x1 - a.x0 >= a.y1 - a.y0)
    lo.x1 = hi.x0 = (a.x0 + a.x1) / 2;
  else
    lo.y1 = hi.y0 = (a.y0 + a.y1) / 2;
  split(t, lo, range, in, out);
  split(t, hi, range, in, out);
}

const std::vector<texture_streamer::leaf>& texture_streamer::leaves(const stream_texture& t) {
  if (auto it = leaves_.find(t.id); it != leaves_.end()) return it->second;
  const triangle_range range =
      t.triangles.value_or(triangle_range{0, static_cast<std::uint32_t>(ps_.triangles.size())});
  std::vector<std::uint32_t> all;
  for (std::uint32_t i = range.first; i < range.end; ++i) all.push_back(i);
  std::vector<leaf>& out = leaves_[t.id];
  if (area_.x0 < area_.x1 && area_.y0 < area_.y1) split(t, area_, range, all, out);
  return out;
}

// The stride and TBP0 page that keep most of the leaf's cells where they already are (ties: the
// smaller stride, then the lower page), every cell inside the window; then the uploads of the rest.
stream_piece texture_streamer::place(const stream_texture& t, const leaf& l) {
  struct choice {
    std::uint32_t w = 0, base = 0;
    std::size_t kept = 0;
    arrangement a;
  };
  std::optional<choice> best;
  auto inside = [&](std::uint32_t base, const arrangement& a) {
    for (std::uint32_t p : a.at)
      if (const std::uint32_t page = (base + p) % memory_pages; page < first_ || page >= end_) return false;
    return true;
  };
  for (std::uint32_t w : strides(t)) {
    std::optional<arrangement> a = arrange(l.cells, w);
    if (!a || a->length > window_pages()) continue;
    std::map<std::uint32_t, std::size_t> kept;  // TBP0 page -> cells already in place under it
    kept[(first_ + memory_pages - a->first) % memory_pages] = 0;
    for (std::size_t i = 0; i < l.cells.size(); ++i)
      if (const auto it = where_.find({t.id, l.cells[i][0], l.cells[i][1]}); it != where_.end())
        ++kept[(it->second + memory_pages - a->at[i]) % memory_pages];
    for (const auto& [base, n] : kept)
      if ((!best || n > best->kept) && inside(base, *a)) best = choice{w, base, n, *a};
  }
  if (!best) throw std::logic_error("texture_streamer: a leaf that does not fit");  // split() made every leaf fit
  stream_piece piece{
      l.area,
      l.triangles,
      {fixed::uint<14>::from_wrapped(32 * best->base), fixed::uint<6>::from_wrapped(tbw(t.PSM, best->w)), t.PSM},
      {}};
  for (std::size_t i = 0; i < l.cells.size(); ++i) {
    const std::uint32_t page = (best->base + best->a.at[i]) % memory_pages;
    resident& now = window_[page];
    if (now.id == t.id && now.c == l.cells[i][0] && now.r == l.cells[i][1]) continue;
    if (now.id >= 0) where_.erase({now.id, now.c, now.r});
    now = {t.id, l.cells[i][0], l.cells[i][1]};
    where_[{t.id, now.c, now.r}] = page;
    piece.uploads.push_back({page, now.c, now.r});
  }
  return piece;
}

std::vector<stream_piece> texture_streamer::next_pass(const stream_texture& t) {
  const std::vector<leaf>& ls = leaves(t);
  // Every other pass in reverse, so that it starts where the last one ended; pieces over the same
  // rectangle (a row split by triangles) stay in triangle order.
  const bool reverse = passes_[t.id]++ % 2 == 1;
  std::vector<stream_piece> out;
  for (std::size_t k = 0; k < ls.size();) {
    std::size_t run = k + 1;  // leaves [k, run) share one rectangle
    const std::size_t at = reverse ? ls.size() - 1 - k : k;
    while (run < ls.size() && ls[reverse ? ls.size() - 1 - run : run].area == ls[at].area) ++run;
    for (std::size_t j = 0; j < run - k; ++j) out.push_back(place(t, ls[reverse ? ls.size() - run + j : k + j]));
    k = run;
  }
  return out;
}

const gs::mem::texel_addresses& texture_streamer::addresses(const stream_texture& t, const gs::mem::buffer& at) {
  const std::array<std::uint32_t, 3> key{static_cast<std::uint32_t>(t.id), static_cast<std::uint32_t>(at.PSM),
                                         static_cast<std::uint32_t>(at.BW.value())};
  std::unique_ptr<const gs::mem::texel_addresses>& table = tables_[key];
  if (!table)
    table = std::make_unique<const gs::mem::texel_addresses>(t.PSM, at.BW.value(), static_cast<std::uint32_t>(t.width),
                                                             static_cast<std::uint32_t>(t.height));
  return *table;
}

void add_piece_uploads(gs::packets::packet_builder& b, const stream_texture& t, const stream_piece& p) {
  const gs::mem::extent pg = page_of(t.PSM);
  const auto bpp = static_cast<std::size_t>(bytes_per_texel(t.PSM));
  std::vector<std::uint8_t> image;
  for (const cell_upload& u : p.uploads) {
    const int x0 = u.c * static_cast<int>(pg.w), y0 = u.r * static_cast<int>(pg.h);
    const int w = std::min(static_cast<int>(pg.w), t.width - x0), h = std::min(static_cast<int>(pg.h), t.height - y0);
    image.clear();
    for (int y = y0; y < y0 + h; ++y) {
      const auto row = t.texels.subspan(
          (static_cast<std::size_t>(y) * static_cast<std::size_t>(t.width) + static_cast<std::size_t>(x0)) * bpp,
          static_cast<std::size_t>(w) * bpp);
      image.insert(image.end(), row.begin(), row.end());
    }
    const gs::mem::buffer page{fixed::uint<14>::from_wrapped(32 * u.page), fixed::uint<6>::from_wrapped(tbw(t.PSM, 1)),
                               t.PSM};
    host_transfer(b, page, w, h, image);
  }
}

void upload_piece(gs::mem::local_memory& m, const stream_texture& t, const stream_piece& p) {
  if (p.uploads.empty()) return;
  gs::packets::packet_builder b;
  add_piece_uploads(b, t, p);
  interpret(m, b);
}

}  // namespace gsdot3::pipeline
