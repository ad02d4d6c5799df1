// pipeline/child_process.cpp — fork, pipe, rlimit (see child_process.hpp).
#include "pipeline/child_process.hpp"

#include <cerrno>
#include <csignal>
#include <new>
#include <stdexcept>

#include <fcntl.h>
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

}  // namespace

std::string run_in_child(const std::function<std::string()>& work, std::size_t address_space_limit, rlim_t cpu_seconds) {
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
    const int null = ::open("/dev/null", O_WRONLY);  // the parser's own complaints (assert text) stay out of gsdot3's one-line errors
    if (null >= 0) ::dup2(null, STDERR_FILENO);
#if !defined(__SANITIZE_ADDRESS__)  // ASan reserves terabytes of shadow address space up front
    const rlimit cap{address_space_limit, address_space_limit};
    ::setrlimit(RLIMIT_AS, &cap);
#endif
    const rlimit cpu{cpu_seconds, cpu_seconds + 1};  // a parser stuck in a loop gets SIGXCPU
    ::setrlimit(RLIMIT_CPU, &cpu);
    std::string out(1, 'O');
    try {
      out.append(work());
    } catch (const std::bad_alloc&) {
      out.assign(1, 'M');
    } catch (const std::exception& e) {
      out.assign(1, 'E');
      out.append(e.what());
    }
    write_all(fds[1], out);
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string got;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string gib = std::to_string(address_space_limit >> 30);
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
    throw std::runtime_error("the reader used more than " + std::to_string(cpu_seconds) + " s of CPU (stuck on a malformed file?)");
  if (WIFSIGNALED(status)) throw std::runtime_error("the reader crashed (signal " + std::to_string(WTERMSIG(status)) + "): a malformed file");
  if (got.empty() || got[0] == 'M') throw std::runtime_error("the reader ran out of memory (more than " + gib + " GiB): a malformed or huge file");
  if (got[0] == 'E') throw std::runtime_error(got.substr(1));
  return got.substr(1);
}

}  // namespace gsdot3::pipeline
