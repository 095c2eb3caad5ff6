#include "harness/run/run_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace cyclecert {

std::string RunLock::lockPath(const std::string& outDir) { return outDir + "/run.lock"; }

std::string commandLineText(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& a : argv) text += (text.empty() ? "" : " ") + a;
  return text;
}

namespace {

// What the holding run wrote into the lock file (its pid and command line), "" when unknown.
std::string holderText(int fd) {
  char buffer[1024];
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  if (n <= 0) return "";
  std::string text(buffer, static_cast<std::size_t>(n));
  if (const auto end = text.find('\n'); end != std::string::npos) text.erase(end);
  return text;
}

}  // namespace

RunLock::RunLock(const std::string& outDir, const std::string& holder) {
  std::filesystem::create_directories(outDir);
  const std::string path = lockPath(outDir);
  // O_CLOEXEC: an engine's process must not inherit (and so keep) the lock.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOCTTY, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot lock '" + outDir + "': cannot open " + path + ": " + std::strerror(errno));
  int taken = 0;
  do taken = ::flock(fd_, LOCK_EX | LOCK_NB);
  while (taken != 0 && errno == EINTR);
  if (taken != 0) {
    const int error = errno;
    const std::string other = error == EWOULDBLOCK ? holderText(fd_) : "";
    ::close(fd_);
    fd_ = -1;
    if (error != EWOULDBLOCK) throw std::runtime_error("cannot lock " + path + ": " + std::strerror(error));
    throw RunLockedError("'" + outDir + "' is in use by another cyclecert run" + (other.empty() ? "" : " (" + other + ")") +
                         ", which holds " + path + "; wait for it to end, or give another --out");
  }
  // Who holds it, for the message a second run gets; the lock itself does not depend on it.
  const std::string text = "pid " + std::to_string(::getpid()) + ": " + holder + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, text.data(), text.size(), 0);
  }
}

RunLock::~RunLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace cyclecert
