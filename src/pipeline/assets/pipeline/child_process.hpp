// pipeline/child_process.hpp — running a hostile-input parser where its crash cannot take gsdot3
// down: a forked child with a capped address space, its result passed back as bytes through a
// pipe. assimp 5.2 is a large C++ parser family that can abort on malformed files (its own
// tests/models/invalid/OutOfMemory.off: an ai_assert abort after allocating 15 GB) or loop, so the mesh
// import runs this way (mesh_import.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include <sys/resource.h>

namespace gsdot3::pipeline {

struct child_limits {
  std::size_t address_space;  // RLIMIT_AS of the child (not under ASan, which reserves terabytes of shadow)
  rlim_t cpu_seconds;         // RLIMIT_CPU: a child looping is killed by SIGXCPU
  int wall_seconds;           // the parent's deadline: a child that waits without using CPU is killed (SIGKILL)
};

// Returns what work() returned in the child. Throws std::runtime_error with the child's
// std::runtime_error message, or "the reader crashed (signal N)" / "stopped with exit code N" /
// "ran out of memory" / "used more than S s of CPU" / "did not finish within W s" when the child
// died, exited without a result, failed to allocate, looped (assimp 5.2's PLY reader loops on
// some malformed headers: found by fuzz/parse_inputs) or waited. The last was found by
// fuzz/parse_inputs in CI: a child still running after 29 minutes without reaching its 120 s CPU
// limit, the parent blocked reading the pipe. Its children then had their address space capped
// under ASan (clang 14 does not define __SANITIZE_ADDRESS__) and died in ASan's "Failed to mmap" with
// libFuzzer's inherited crash handler; a child that never finishes dying is the likely case, not a
// proven one. The child now runs with default signal handlers, stdin from /dev/null, stderr
// discarded. Call it before starting threads.
std::string run_in_child(const std::function<std::string()>& work, const child_limits& limits);

}  // namespace gsdot3::pipeline
