// pipeline/child_process.hpp — running a hostile-input parser where its crash cannot take gsdot3
// down: a forked child with a capped address space, its result passed back as bytes through a
// pipe. assimp 5.2 is a large C++ parser family that can abort on malformed files (its own
// tests/models/invalid/OutOfMemory.off: an ai_assert abort after allocating 15 GB), so the mesh
// import runs this way (mesh_import.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace gsdot3::pipeline {

// Returns what work() returned in the child. Throws std::runtime_error with the child's
// std::runtime_error message, or "the reader crashed (signal N)" / "the reader ran out of memory
// (more than L GiB)" when the child died or failed to allocate. Call it before starting threads.
std::string run_in_child(const std::function<std::string()>& work, std::size_t address_space_limit);

}  // namespace gsdot3::pipeline
