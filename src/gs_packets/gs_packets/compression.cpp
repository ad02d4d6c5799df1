// .gs.xz and .gs.zst: the whole dump as one stream (PCSX2 `GSDumpXz`: lzma_easy_encoder level 6,
// LZMA_CHECK_CRC64; `GSDumpZst`: ZSTD compression level 6), through Debian's liblzma and libzstd.
#include <lzma.h>
#include <zstd.h>

#include <cctype>
#include <string>

#include "gs_packets/dump.hpp"

namespace gs::dump {

compression compression_for(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".xz") return compression::xz;
  if (ext == ".zst") return compression::zstd;
  return compression::none;
}

std::vector<std::uint8_t> compress(std::span<const std::uint8_t> raw, compression c) {
  if (c == compression::none) return {raw.begin(), raw.end()};
  if (c == compression::xz) {
    std::vector<std::uint8_t> out(lzma_stream_buffer_bound(raw.size()));
    std::size_t pos = 0;
    if (lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, raw.data(), raw.size(), out.data(), &pos, out.size()) !=
        LZMA_OK)
      throw dump_error("xz: compression failed");
    out.resize(pos);
    return out;
  }
  std::vector<std::uint8_t> out(ZSTD_compressBound(raw.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 6);
  if (ZSTD_isError(n)) throw dump_error(std::string("zstd: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

namespace {

std::vector<std::uint8_t> unxz(std::span<const std::uint8_t> in) {
  lzma_stream s = LZMA_STREAM_INIT;
  if (lzma_stream_decoder(&s, UINT64_MAX, LZMA_CONCATENATED) != LZMA_OK) throw dump_error("xz: decoder init failed");
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> buf(1 << 20);
  s.next_in = in.data();
  s.avail_in = in.size();
  lzma_ret ret = LZMA_OK;
  while (ret == LZMA_OK) {
    s.next_out = buf.data();
    s.avail_out = buf.size();
    ret = lzma_code(&s, LZMA_FINISH);
    out.insert(out.end(), buf.data(), buf.data() + (buf.size() - s.avail_out));
  }
  const std::size_t consumed = in.size() - s.avail_in;
  lzma_end(&s);
  if (ret != LZMA_STREAM_END)
    throw dump_error("xz: corrupt or truncated stream at compressed byte " + std::to_string(consumed) +
                     " (lzma error " + std::to_string(static_cast<int>(ret)) + ")");
  return out;
}

std::vector<std::uint8_t> unzstd(std::span<const std::uint8_t> in) {
  ZSTD_DStream* z = ZSTD_createDStream();
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> buf(ZSTD_DStreamOutSize());
  ZSTD_inBuffer ib{in.data(), in.size(), 0};
  std::size_t ret = 1;
  while (ib.pos < ib.size || ret != 0) {
    ZSTD_outBuffer ob{buf.data(), buf.size(), 0};
    ret = ZSTD_decompressStream(z, &ob, &ib);
    if (ZSTD_isError(ret)) {
      const std::string msg = ZSTD_getErrorName(ret);
      ZSTD_freeDStream(z);
      throw dump_error("zstd: " + msg + " at compressed byte " + std::to_string(ib.pos));
    }
    out.insert(out.end(), buf.data(), buf.data() + ob.pos);
    if (ib.pos == ib.size && ob.pos < ob.size && ret != 0) {
      ZSTD_freeDStream(z);
      throw dump_error("zstd: truncated stream (" + std::to_string(in.size()) + " compressed bytes)");
    }
  }
  ZSTD_freeDStream(z);
  return out;
}

}  // namespace

std::vector<std::uint8_t> decompress(std::span<const std::uint8_t> file) {
  static constexpr std::uint8_t xz_magic[6] = {0xFD, 0x37, 0x7A, 0x58, 0x5A, 0x00};
  static constexpr std::uint8_t zstd_magic[4] = {0x28, 0xB5, 0x2F, 0xFD};
  if (file.size() >= 6 && std::equal(xz_magic, xz_magic + 6, file.begin())) return unxz(file);
  if (file.size() >= 4 && std::equal(zstd_magic, zstd_magic + 4, file.begin())) return unzstd(file);
  return {file.begin(), file.end()};
}

}  // namespace gs::dump
