// fuzz/dump_reader.cpp — the GS dump reader (gs_packets/dump.hpp) on any bytes: decompress, read_dump
// and decode_paths either succeed or throw dump_error (nothing else, no crash); a dump that reads
// back re-serialises to bytes that read back to the same bytes again. A dump that decodes is then
// replayed through the packet interpreter with drawing (gs_packets/interpreter.hpp, skipping what the
// model lacks) and its displayed frame decoded: neither may throw.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <string>

#include "fuzz_check.hpp"
#include "gs_packets/display.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gs::dump;
  try {
    const gs_dump d = read_dump(decompress(std::span<const std::uint8_t>(data, size)));
    decode_paths(d);
    const auto once = write_dump(d);
    gsdot3::fuzz::require(write_dump(read_dump(once)) == once,
                          [] { return std::string("write(read(write(d))) != write(d)"); });
    gs::mem::local_memory m;
    gs::packets::interpreter it(m, {.skip_unmodelled = true});
    it.replay(d);
    gs::packets::decode_display(it.privileged());
  } catch (const dump_error&) {
  } catch (const std::exception& e) {
    gsdot3::fuzz::fail(std::string("dump_reader: unexpected exception: ") + e.what());
  }
  return 0;
}
