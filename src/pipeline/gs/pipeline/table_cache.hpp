// pipeline/table_cache.hpp — gs_memory's address tables (texel_addresses, row_column_address) kept
// between frames. A table depends only on its constructor's arguments, and building a frame's tables
// again (locate and unit_address over every texel, row and column) took about 8 % of a memory-path
// frame at one thread (perf, AMD EPYC with AVX-512, 2026-12-07), all of it before the bands start.
// At most `kept` tables are held; when full, all are dropped. Thread-safe; a table is immutable.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace gsdot3::pipeline::detail {

template <class Table, class... Args>
std::shared_ptr<const Table> cached_table(Args... args) {
  constexpr std::size_t kept = 32;
  static std::mutex m;
  static std::map<std::tuple<Args...>, std::shared_ptr<const Table>> tables;
  const std::lock_guard lock(m);
  std::shared_ptr<const Table>& t = tables[std::make_tuple(args...)];
  if (t == nullptr) {
    if (tables.size() > kept) {
      tables.clear();
      return tables[std::make_tuple(args...)] = std::make_shared<const Table>(args...);
    }
    t = std::make_shared<const Table>(args...);
  }
  return t;
}

}  // namespace gsdot3::pipeline::detail
