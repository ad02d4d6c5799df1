// run_in_child's contract (child_process.hpp): the child's result or its error message comes
// back, and a child that loops, waits or reads stdin cannot hold gsdot3 up. Each expected value
// is what the work function was written to do.
#include <gtest/gtest.h>

#include "expect_error.hpp"

#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "pipeline/child_process.hpp"

namespace gsdot3::pipeline {
namespace {

using test::expect_error;

constexpr child_limits generous{std::size_t{1} << 30, 30, 60};

TEST(ChildProcess, ResultAndErrorComeBack) {
  EXPECT_EQ(run_in_child([] { return std::string(100000, 'x') + "end"; }, generous), std::string(100000, 'x') + "end");
  expect_error(
      [] { run_in_child([]() -> std::string { throw std::runtime_error("bad header at byte 7"); }, generous); },
      "bad header at byte 7");
}

TEST(ChildProcess, ChildAllocatesUpToItsCap) {
  // 256 MiB under a 1 GiB cap (no cap under ASan, whose shadow would make every new mapping fail).
  const std::string got = run_in_child(
      [] { return std::to_string(std::vector<char>(std::size_t{256} << 20, 'a').size() >> 20); }, generous);
  EXPECT_EQ(got, "256");
}

TEST(ChildProcess, ChildDiesOfASignalWhateverHandlerTheParentInstalled) {
  // A handler that ends the process quietly, as a fuzzer's crash handler does after writing its
  // artifact: the child must not run it.
  const auto previous = std::signal(SIGABRT, [](int) { ::_exit(0); });
  expect_error([] { run_in_child([]() -> std::string { std::abort(); }, generous); }, "the reader crashed (signal 6)");
  std::signal(SIGABRT, previous);
}

TEST(ChildProcess, StdinReadsAsEmpty) {
  const std::string got = run_in_child(
      [] {
        char c = 0;
        return std::to_string(::read(STDIN_FILENO, &c, 1));
      },
      generous);
  EXPECT_EQ(got, "0");  // end of file at once: /dev/null, whatever stdin the caller has
}

TEST(ChildProcess, ChildThatWaitsIsStoppedAtTheWallDeadline) {
  expect_error(
      [] {
        run_in_child(
            []() -> std::string {
              for (;;) ::pause();
            },
            {std::size_t{1} << 30, 30, 1});
      },
      "the reader did not finish within 1 s and was stopped");
}

TEST(ChildProcess, ChildThatLoopsIsStoppedAtTheCpuLimit) {
  expect_error(
      [] {
        run_in_child(
            []() -> std::string {
              volatile unsigned spin = 0;
              for (;;) spin = spin + 1;
            },
            {std::size_t{1} << 30, 1, 60});
      },
      "the reader used more than 1 s of CPU");
}

}  // namespace
}  // namespace gsdot3::pipeline
