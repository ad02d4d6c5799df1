// pipeline/atomic_file.cpp — files and folders that appear whole or not at all (files.hpp).
#include <algorithm>
#include <fstream>
#include <string>
#include <vector>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline {

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw std::runtime_error(file.string() + ": cannot write");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(file.string() + ": cannot rename the written file into place: " + ec.message());
  }
}

namespace {

// A sibling of `target` that does not exist yet: TARGET.KIND-PID-N.
std::filesystem::path fresh_sibling(const std::filesystem::path& target, const char* kind) {
  const std::filesystem::path base = target.has_filename() ? target : target.parent_path();
  for (int n = 0;; ++n) {
    std::string suffix = ".";  // appended piecewise: g++ 12 warns falsely (-Wrestrict) on a chain of +
    suffix.append(kind).append("-").append(std::to_string(::getpid())).append("-").append(std::to_string(n));
    std::filesystem::path p = base;
    p += suffix;
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) return p;
  }
}

}  // namespace

staged_directory::staged_directory(std::filesystem::path target) : target_(std::move(target)) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec))
    throw std::runtime_error(target_.string() + ": exists and is not a directory");
  if (const fs::path parent = fs::absolute(target_, ec).parent_path(); !fs::is_directory(parent, ec)) {
    fs::create_directories(parent, ec);
    if (ec) throw std::runtime_error(target_.string() + ": cannot create the output directory (" + ec.message() + ")");
  }
  staging_ = fresh_sibling(target_, "partial");
  if (!fs::create_directory(staging_, ec) || ec)
    throw std::runtime_error(target_.string() + ": cannot create the output directory beside it (" +
                             (ec ? ec.message() : std::string("exists")) + ")");
}

staged_directory::~staged_directory() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

void staged_directory::commit(const std::vector<std::string>& last) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(target_, ec)) {
    fs::rename(staging_, target_, ec);
    if (ec) throw std::runtime_error(target_.string() + ": cannot put the output in place (" + ec.message() + ")");
    committed_ = true;
    return;
  }
  // Into the existing folder file by file (each rename replaces one file whole), `last` at the end.
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(staging_, ec)) files.push_back(e.path().filename());
  std::stable_partition(files.begin(), files.end(), [&](const fs::path& f) {
    return std::find(last.begin(), last.end(), f.string()) == last.end();
  });
  for (const fs::path& f : files) {
    if (fs::is_directory(target_ / f, ec) != fs::is_directory(staging_ / f, ec)) fs::remove_all(target_ / f, ec);
    fs::rename(staging_ / f, target_ / f, ec);
    if (ec)
      throw std::runtime_error((target_ / f).string() + ": cannot put the output in place (" + ec.message() + ")");
  }
  fs::remove_all(staging_, ec);
  committed_ = true;
}

}  // namespace gsdot3::pipeline
