// fuzz/dump_reader.cpp — the GS dump reader (gs_packets/dump.hpp) on any bytes: decompress, read_dump
// and decode_paths either succeed or throw dump_error (nothing else, no crash); a dump that reads
// back re-serialises to bytes that read back to the same bytes again.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <string>

#include "fuzz_check.hpp"
#include "gs_packets/dump.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gs::dump;
  try {
    const gs_dump d = read_dump(decompress(std::span<const std::uint8_t>(data, size)));
    decode_paths(d);
    const auto once = write_dump(d);
    gsdot3::fuzz::require(write_dump(read_dump(once)) == once, [] { return std::string("write(read(write(d))) != write(d)"); });
  } catch (const dump_error&) {
  } catch (const std::exception& e) {
    gsdot3::fuzz::fail(std::string("dump_reader: unexpected exception: ") + e.what());
  }
  return 0;
}
