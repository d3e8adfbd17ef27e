#include "render/app/gnuplot.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <fmt/core.h>

#include "render/app/sigint_guard.h"

extern char** environ;

namespace rugosim::app {
namespace {

// A file descriptor closed when it goes out of scope.
class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

// Writes all of `text`; false when the reader went away (EPIPE) or another error occurred.
bool write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::string read_all(int fd) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) != 0) return text;
  char buffer[4096];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  return text;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return status;
}

std::string system_error(std::string_view what) {
  return fmt::format("{}: {}", what, std::strerror(errno));
}

}  // namespace

std::string gnuplot_quote(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out.append("''");
    } else if (static_cast<unsigned char>(c) < 0x20 || c == '\x7f') {
      out.push_back(' ');
    } else {
      out.push_back(c);
    }
  }
  out.push_back('\'');
  return out;
}

std::string run_gnuplot(std::string_view script, const std::string& output_path) {
  const Fd output(::open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
  if (output.get() < 0) throw GnuplotError(system_error(output_path + ": cannot create"));
  // gnuplot's messages go to an unnamed temporary file rather than a second pipe: reading a pipe
  // while writing the script to the other would need poll() to avoid a deadlock.
  std::FILE* messages_file = std::tmpfile();
  if (messages_file == nullptr) {
    throw GnuplotError(system_error("cannot create a temporary file for gnuplot's messages"));
  }
  const Fd messages(::dup(::fileno(messages_file)));
  std::fclose(messages_file);
  if (messages.get() < 0) throw GnuplotError(system_error("cannot duplicate a file descriptor"));
  ::fcntl(messages.get(), F_SETFD, FD_CLOEXEC);

  int ends[2] = {-1, -1};
  if (::pipe2(ends, O_CLOEXEC) != 0) throw GnuplotError(system_error("cannot create a pipe"));
  const Fd read_end(ends[0]);
  Fd write_end(ends[1]);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // dup2 clears close-on-exec on the copies, so gnuplot gets exactly these three descriptors.
  posix_spawn_file_actions_adddup2(&actions, read_end.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, output.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, messages.get(), STDERR_FILENO);
  std::string program = "gnuplot", default_settings = "-d";
  char* argv[] = {program.data(), default_settings.data(), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    if (spawned == ENOENT) {
      throw GnuplotError(
          "cannot run gnuplot: not found on PATH; install it (Debian: apt-get install "
          "gnuplot-nox)");
    }
    throw GnuplotError(fmt::format("cannot run gnuplot: {}", std::strerror(spawned)));
  }

  bool written = false;
  {
    // SIGPIPE ignored while the script is written, so that a gnuplot that exits early (on an
    // error) shows up as EPIPE and is reported with its messages instead of killing rugosim.
    const ScopedSignalHandler ignore_sigpipe(SIGPIPE, SIG_IGN);
    written = write_all(write_end.get(), script);
    write_end.reset();  // end of the script: gnuplot finishes the plot and exits
  }
  const int status = wait_for(pid);
  const std::string said = read_all(messages.get());
  const std::string tail = said.empty() ? std::string() : fmt::format(":\n{}", said);
  if (status < 0) throw GnuplotError(system_error("cannot wait for gnuplot"));
  if (WIFSIGNALED(status)) {
    throw GnuplotError(fmt::format("gnuplot was killed by signal {} ({}){}", WTERMSIG(status),
                                   strsignal(WTERMSIG(status)), tail));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw GnuplotError(
        fmt::format("gnuplot failed with exit status {}{}", WEXITSTATUS(status), tail));
  }
  if (!written) throw GnuplotError(fmt::format("gnuplot stopped reading its script{}", tail));
  struct stat info {};
  if (::fstat(output.get(), &info) != 0 || info.st_size == 0) {
    throw GnuplotError(fmt::format("gnuplot exited without writing anything{}", tail));
  }
  return said;
}

}  // namespace rugosim::app
