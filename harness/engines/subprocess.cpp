#include "harness/engines/subprocess.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <system_error>
#include <thread>

extern char** environ;

namespace cyclecert {

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void throwErrno(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

// Milliseconds left before the deadline, rounded up (poll's timeout), 0 once it has passed.
int millisecondsUntil(Deadline deadline) {
  const double left = std::chrono::duration<double, std::milli>(deadline - Clock::now()).count();
  if (left <= 0) return 0;
  return static_cast<int>(std::min(std::ceil(left), static_cast<double>(INT_MAX)));
}

bool passed(Deadline deadline) { return Clock::now() >= deadline; }

// A pipe whose ends are closed on exec (both) and non-blocking on our side only.
struct Pipe {
  int read = -1, write = -1;
};

void closeAll(std::initializer_list<int> fds) {
  for (int fd : fds) {
    if (fd >= 0) ::close(fd);
  }
}

Pipe makePipe(bool ourEndIsRead, std::initializer_list<int> closeOnFailure) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    const int saved = errno;
    closeAll(closeOnFailure);
    errno = saved;
    throwErrno("pipe");
  }
  const int ours = ourEndIsRead ? fds[0] : fds[1];
  ::fcntl(ours, F_SETFL, ::fcntl(ours, F_GETFL) | O_NONBLOCK);
  return {fds[0], fds[1]};
}

// In the child: `fd` becomes `target` and stays open across exec.
bool moveTo(int fd, int target) {
  if (fd == target) return ::fcntl(fd, F_SETFD, 0) == 0;
  return ::dup2(fd, target) >= 0;
}

// In the child, before exec: every descriptor above stderr closed — ours are close-on-exec, but
// others of the process (a results file, descriptors we inherited) may not be.
void closeInherited() {
  if (::syscall(SYS_close_range, 3u, ~0u, 0u) == 0) return;
  const long most = ::sysconf(_SC_OPEN_MAX);
  for (int fd = 3; fd < (most > 0 && most < 65536 ? most : 65536); ++fd) ::close(fd);
}

ExitStatus statusFrom(const siginfo_t& info) {
  ExitStatus s;
  if (info.si_code == CLD_EXITED) s.exitCode = info.si_status;
  else s.signal = info.si_status;
  return s;
}

// SIGPIPE blocked in this thread while it lives; a SIGPIPE raised meanwhile (by a write to a pipe
// nobody reads) is consumed before the old mask comes back, so it is never delivered.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  ~SigpipeBlocked() {
    if (raised_ && !wasPending_) {
      const timespec now{0, 0};
      while (sigtimedwait(&pipe_, nullptr, &now) < 0 && errno == EINTR) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;
  void raised() { raised_ = true; }

 private:
  sigset_t pipe_, old_;
  bool wasPending_ = false, raised_ = false;
};

}  // namespace

Deadline deadlineAfter(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

std::string ExitStatus::describe() const {
  if (signal != 0) {
    const char* name = ::strsignal(signal);
    return "was killed by signal " + std::to_string(signal) + " (" + (name ? name : "unknown") + ")";
  }
  return "exited with status " + std::to_string(exitCode);
}

Subprocess::Subprocess(const SubprocessSpec& spec) {
  // Everything the child needs is built before fork: the child calls async-signal-safe functions only.
  std::vector<std::string> args = spec.argv, env = spec.environment.value_or(std::vector<std::string>{});
  std::vector<char*> argv, envp;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  char* const* const environment = spec.environment ? envp.data() : environ;
  const char* const cwd = spec.workingDirectory.empty() ? nullptr : spec.workingDirectory.c_str();

  Pipe in, out, err;
  if (spec.stdinPipe) in = makePipe(false, {});
  out = makePipe(true, {in.read, in.write});
  if (spec.stderrPipe) err = makePipe(true, {in.read, in.write, out.read, out.write});
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int saved = errno;
    closeAll({in.read, in.write, out.read, out.write, err.read, err.write});
    errno = saved;
    throwErrno("fork");
  }
  if (pid == 0) {
    ::setpgid(0, 0);                       // its own group: a kill reaches the engine's children too
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);    // and it dies with us: a killed run leaves no engine behind
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::signal(SIGPIPE, SIG_DFL);
    const int stdinFd = spec.stdinPipe ? in.read : ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (stdinFd < 0 || !moveTo(stdinFd, STDIN_FILENO) || !moveTo(out.write, STDOUT_FILENO) ||
        (spec.stderrPipe && !moveTo(err.write, STDERR_FILENO)) || (cwd && ::chdir(cwd) != 0)) {
      ::_exit(127);
    }
    closeInherited();
    ::execve(argv[0], argv.data(), environment);
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from here, so a kill right after fork finds the group
  closeAll({in.read, out.write, err.write});
  pid_ = pid;
  in_ = in.write;
  out_ = out.read;
  err_ = err.read;
}

Subprocess::~Subprocess() { kill(); }

void Subprocess::closePipes() {
  closeAll({in_, out_, err_});
  in_ = out_ = err_ = -1;
}

IoResult Subprocess::write(std::string_view data, Deadline deadline) {
  if (in_ < 0) return IoResult::Closed;
  SigpipeBlocked guard;
  while (!data.empty()) {
    const ssize_t n = ::write(in_, data.data(), data.size());
    if (n > 0) {
      data.remove_prefix(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EPIPE) {
      guard.raised();
      return IoResult::Closed;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) throwErrno("write");
    pollfd p{in_, POLLOUT, 0};  // the pipe is full: wait for room
    if (::poll(&p, 1, millisecondsUntil(deadline)) < 0 && errno != EINTR) throwErrno("poll");
    if (passed(deadline) && !(p.revents & (POLLOUT | POLLERR))) return IoResult::TimedOut;
  }
  return IoResult::Done;
}

IoResult Subprocess::read(std::string& out, std::string* err, Deadline deadline) {
  char chunk[65536];
  for (;;) {
    pollfd fds[2];
    nfds_t count = 0;
    for (int fd : {out_, err_}) {
      if (fd >= 0) fds[count++] = {fd, POLLIN, 0};
    }
    if (count == 0) return IoResult::Closed;
    const int ready = ::poll(fds, count, millisecondsUntil(deadline));
    if (ready < 0 && errno != EINTR) throwErrno("poll");
    if (ready <= 0) {
      if (passed(deadline)) return IoResult::TimedOut;
      continue;
    }
    bool progressed = false;
    for (nfds_t i = 0; i < count; ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      int& fd = fds[i].fd == out_ ? out_ : err_;
      const ssize_t n = ::read(fd, chunk, sizeof chunk);
      if (n > 0) {
        if (&fd == &out_) out.append(chunk, static_cast<std::size_t>(n));
        else if (err) err->append(chunk, static_cast<std::size_t>(n));
        progressed = true;
      } else if (n == 0 || (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK)) {
        ::close(fd);
        fd = -1;
        progressed = true;
      }
    }
    if (out_ < 0 && err_ < 0) return IoResult::Closed;
    if (progressed) return IoResult::Done;
  }
}

std::string Subprocess::readWaiting(std::size_t limit) {
  std::string text;
  char chunk[4096];
  while (out_ >= 0 && text.size() < limit) {
    const ssize_t n = ::read(out_, chunk, std::min(sizeof chunk, limit - text.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // nothing waiting (EAGAIN), or its end: the next read says which
    text.append(chunk, static_cast<std::size_t>(n));
  }
  return text;
}

std::optional<ExitStatus> Subprocess::endedBy(Deadline deadline) {
  if (reaped_) return reaped_;
  if (pid_ < 0) return std::nullopt;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    siginfo_t info{};
    // WNOWAIT: it stays a zombie, so its group number stays ours until kill() reaps it.
    const int r = ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT);
    if (r < 0 && errno == EINTR) continue;
    if (r == 0 && info.si_pid == pid_) return statusFrom(info);
    if (r < 0 || passed(deadline)) return std::nullopt;
    std::this_thread::sleep_for(std::min<Clock::duration>(pause, deadline - Clock::now()));
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
}

ExitStatus Subprocess::kill() {
  closePipes();
  if (reaped_) return *reaped_;
  if (pid_ < 0) return {};
  ::kill(-pid_, SIGKILL);
  ::kill(pid_, SIGKILL);
  int status = 0;
  pid_t r;
  while ((r = ::waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
  }
  ExitStatus s;
  if (r == pid_ && WIFEXITED(status)) s.exitCode = WEXITSTATUS(status);
  if (r == pid_ && WIFSIGNALED(status)) s.signal = WTERMSIG(status);
  reaped_ = s;
  return s;
}

}  // namespace cyclecert
