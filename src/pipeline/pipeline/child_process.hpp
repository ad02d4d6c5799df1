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

// Returns what work() returned in the child. Throws std::runtime_error with the child's
// std::runtime_error message, or "the reader crashed (signal N)" / "ran out of memory" / "used
// more than S s of CPU" when the child died, failed to allocate or looped (assimp 5.2's PLY reader
// loops on some malformed headers: found by fuzz/parse_inputs). Call it before starting threads.
std::string run_in_child(const std::function<std::string()>& work, std::size_t address_space_limit, rlim_t cpu_seconds);

}  // namespace gsdot3::pipeline
