#pragma once
// One subprocess layer for the engines that run another program (process:COMMAND, LinuxCNC's rs274):
// start it with pipes, write to it and read from it under a deadline, and end it — so that no engine
// can make the run wait without limit, kill the run, or leak descriptors into other children.
//
// - Pipes are close-on-exec; a failed fork closes every one of them; the child closes every other
//   descriptor above stderr before exec (close_range), so it inherits only stdin, stdout, stderr.
// - The child gets its own process group (killed whole: an engine's own children too) and dies with
//   us (PR_SET_PDEATHSIG), starts with no blocked signals and SIGPIPE at its default.
// - Every wait has a deadline: writes are non-blocking with poll(POLLOUT), reads poll(POLLIN).
// - A write to a process that stopped reading fails (IoResult::Closed) instead of raising SIGPIPE:
//   SIGPIPE is blocked in the writing thread around the write, and one the write raised is consumed
//   with sigtimedwait — the process-wide disposition is never touched.
// - waitpid is retried on EINTR; the group is killed before the leader is reaped, so the group's
//   number cannot have been reused.
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cyclecert {

using Deadline = std::chrono::steady_clock::time_point;
Deadline deadlineAfter(double seconds);

struct SubprocessSpec {
  std::vector<std::string> argv;                        // argv[0]: the program's path (no PATH search)
  std::optional<std::vector<std::string>> environment;  // "NAME=value"; nothing: ours
  std::string workingDirectory;                         // empty: ours
  bool stdinPipe = true;                                // false: /dev/null
  bool stderrPipe = false;                              // false: ours
};

struct ExitStatus {
  int exitCode = -1;  // when it exited
  int signal = 0;     // when a signal ended it
  std::string describe() const;  // "exited with status 3", "was killed by signal 11 (Segmentation fault)"
};

enum class IoResult { Done, Closed, TimedOut };

class Subprocess {
 public:
  // Starts the program; throws std::system_error ("pipe: …", "fork: …") when it cannot.
  explicit Subprocess(const SubprocessSpec& spec);
  ~Subprocess();  // kills its process group and reaps it
  Subprocess(const Subprocess&) = delete;
  Subprocess& operator=(const Subprocess&) = delete;

  pid_t pid() const { return pid_; }

  // All of `data` to its stdin before the deadline: Done, Closed (it stopped reading) or TimedOut.
  IoResult write(std::string_view data, Deadline deadline);
  // Waits until it writes something (appended to `out`, or to `err` — stderr, when piped; dropped
  // when err is null) or closes an output: Done; Closed once every output is at its end; TimedOut.
  IoResult read(std::string& out, std::string* err, Deadline deadline);
  // What its stdout holds right now (up to `limit` bytes), without waiting.
  std::string readWaiting(std::size_t limit);

  // How it ended, once it has ended before the deadline (not reaped yet: the group is killed first).
  std::optional<ExitStatus> endedBy(Deadline deadline);
  // Kills the group and reaps the process: how it ended.
  ExitStatus kill();

 private:
  void closePipes();

  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;  // our ends of its stdin, stdout, stderr
  std::optional<ExitStatus> reaped_;
};

}  // namespace cyclecert
