#pragma once
// One run at a time per output directory. `check`, `fuzz` and `merge --out` hold an exclusive
// flock(2) on OUT/run.lock while they write OUT's results.jsonl, run.json and report; a second run
// into the same OUT is refused at once instead of interleaving its results with the first's. The
// kernel releases the lock when the process ends however it ends, so a killed run never leaves a
// stale lock behind: the file stays, the lock does not.
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclecert {

// Another run holds OUT's lock; the message names OUT and, as far as it is known, that run.
struct RunLockedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RunLock {
 public:
  // Creates `outDir` if need be and takes its lock, or throws RunLockedError without waiting.
  // `holder` (e.g. the command line) is written into the lock file for the message a second run
  // gets.
  RunLock(const std::string& outDir, const std::string& holder);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  static std::string lockPath(const std::string& outDir);  // OUT/run.lock

 private:
  int fd_ = -1;
};

// The command line as one line of text, for `holder`.
std::string commandLineText(const std::vector<std::string>& argv);

}  // namespace cyclecert
