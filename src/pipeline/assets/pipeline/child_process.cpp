// pipeline/child_process.cpp — fork, pipe, rlimit, deadline (see child_process.hpp).
#include "pipeline/child_process.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <new>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gsdot3::pipeline {

namespace {

void write_all(int fd, const std::string& bytes) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    at += static_cast<std::size_t>(n);
  }
}

// GCC defines __SANITIZE_ADDRESS__ under -fsanitize=address, clang 14 only answers
// __has_feature(address_sanitizer) (the fuzz preset's children had their address space capped and
// died in ASan's "Failed to mmap").
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GSDOT3_ADDRESS_SANITIZER
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(GSDOT3_ADDRESS_SANITIZER)
constexpr bool under_address_sanitizer = true;
#else
constexpr bool under_address_sanitizer = false;
#endif

// Signals whose handlers a sanitizer or fuzzer runtime may have installed in the parent: the child
// dies of them as a plain process would, so its crash is reported as a signal and no inherited
// handler runs (libFuzzer's wrote one crash artifact per assimp abort in the child).
constexpr int reset_signals[] = {SIGABRT, SIGBUS,  SIGFPE,  SIGILL,  SIGSEGV, SIGTRAP, SIGALRM,
                                 SIGINT,  SIGTERM, SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ};

void redirect(int target, int flags) {
  const int null = ::open("/dev/null", flags);
  if (null < 0) return;
  ::dup2(null, target);
  if (null != target) ::close(null);
}

// Reads the child's bytes until it closes the pipe; false when the deadline passed first.
bool read_until(int fd, std::chrono::steady_clock::time_point deadline, std::string& got) {
  char buf[65536];
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return false;
    if (ready < 0) return true;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    got.append(buf, static_cast<std::size_t>(n));
  }
}

}  // namespace

std::string run_in_child(const std::function<std::string()>& work, const child_limits& limits) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for the reader");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("cannot start the reader process");
  }
  if (pid == 0) {  // the child: one status byte ('O' result, 'E' error, 'M' out of memory), then the text
    ::close(fds[0]);
    for (int sig : reset_signals) ::signal(sig, SIG_DFL);
    redirect(STDIN_FILENO, O_RDONLY);  // a file the parser opens by name (/dev/stdin) reads nothing, never the terminal
    redirect(STDERR_FILENO,
             O_WRONLY);              // the parser's own complaints (assert text) stay out of gsdot3's one-line errors
    if (!under_address_sanitizer) {  // ASan reserves terabytes of shadow up front: under a cap its next mmap fails
      const rlimit cap{limits.address_space, limits.address_space};
      ::setrlimit(RLIMIT_AS, &cap);
    }
    const rlimit cpu{limits.cpu_seconds, limits.cpu_seconds + 1};  // a parser stuck in a loop gets SIGXCPU
    ::setrlimit(RLIMIT_CPU, &cpu);
    std::string out(1, 'O');
    try {
      out.append(work());
    } catch (const std::bad_alloc&) { out.assign(1, 'M'); } catch (const std::exception& e) {
      out.assign(1, 'E');
      out.append(e.what());
    }
    write_all(fds[1], out);
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string got;
  const bool finished =
      read_until(fds[0], std::chrono::steady_clock::now() + std::chrono::seconds(limits.wall_seconds), got);
  ::close(fds[0]);
  if (!finished) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (!finished)
    throw std::runtime_error("the reader did not finish within " + std::to_string(limits.wall_seconds) +
                             " s and was stopped: a malformed file?");
  const std::string gib = std::to_string(limits.address_space >> 30);
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
    throw std::runtime_error("the reader used more than " + std::to_string(limits.cpu_seconds) +
                             " s of CPU (stuck on a malformed file?)");
  if (WIFSIGNALED(status))
    throw std::runtime_error("the reader crashed (signal " + std::to_string(WTERMSIG(status)) + "): a malformed file");
  if (got.empty() && WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw std::runtime_error("the reader stopped with exit code " + std::to_string(WEXITSTATUS(status)) +
                             " and no result: a malformed file");
  if (got.empty() || got[0] == 'M')
    throw std::runtime_error("the reader ran out of memory (more than " + gib + " GiB): a malformed or huge file");
  if (got[0] == 'E') throw std::runtime_error(got.substr(1));
  return got.substr(1);
}

}  // namespace gsdot3::pipeline
