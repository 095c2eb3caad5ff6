// process:COMMAND — any program speaking JSON lines: one spec case per line on its stdin, one reply
// per line on its stdout: {"toolpath": {…}}, {"alarm": {"code", "message", "line"}},
// {"not_applicable": "…"} or {"error": "…"}. The process is started once and reused; a crash, a hang
// (per-case timeout), invalid JSON or a reply beyond the size cap is an engine failure for that
// case, the process is restarted for the next one, and the run goes on.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "harness/engines/engines.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert {

namespace {

class ProcessEngine : public Engine {
 public:
  ProcessEngine(std::string command, const EngineOptions& options) : command_(std::move(command)), options_(options) {
    ::signal(SIGPIPE, SIG_IGN);  // a dead engine must not kill the run: writes fail with EPIPE instead
  }
  ~ProcessEngine() override { stop(); }

  std::string name() const override { return "process:" + command_; }
  std::string description() const override { return "external engine `" + command_ + "` (JSON lines)"; }
  std::string version() const override { return command_; }

  EngineResult run(const SpecCase& c) override {
    const auto started = std::chrono::steady_clock::now();
    EngineResult r = exchange(c);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
  }

 private:
  EngineResult exchange(const SpecCase& c) {
    if (pid_ < 0 && !start()) return EngineResult::failed("cannot start `" + command_ + "`: " + std::strerror(errno));
    const std::string request = c.raw.dump() + "\n";
    if (!writeAll(request)) return restartAfter("the engine process stopped reading (it may have crashed)");
    std::string line;
    const std::string problem = readLine(line);
    if (!problem.empty()) return restartAfter(problem);
    return parseReply(line);
  }

  EngineResult parseReply(const std::string& line) {
    nlohmann::json reply;
    try {
      reply = parseJsonDocument(line, "reply");
    } catch (const std::exception& e) {
      return restartAfter(std::string("invalid JSON reply: ") + e.what());
    }
    if (!reply.is_object()) return restartAfter("the reply is not a JSON object");
    try {
      if (reply.contains("toolpath")) return EngineResult::planned(toolpathFromJson(reply["toolpath"]));
      if (reply.contains("alarm")) {
        Toolpath t;
        t.alarm = alarmFromJson(reply["alarm"], "alarm");
        return EngineResult::planned(std::move(t));
      }
      if (reply.contains("not_applicable")) return EngineResult::notApplicable(reply["not_applicable"].dump());
      if (reply.contains("error")) return EngineResult::failed("the engine reported: " + reply["error"].dump());
    } catch (const std::exception& e) {
      return EngineResult::failed(std::string("reply: ") + e.what());
    }
    return EngineResult::failed("a reply with none of toolpath, alarm, not_applicable, error");
  }

  EngineResult restartAfter(const std::string& problem) {
    stop();
    return EngineResult::failed(problem);
  }

  bool start() {
    int toChild[2], fromChild[2];
    if (::pipe(toChild) != 0) return false;
    if (::pipe(fromChild) != 0) {
      ::close(toChild[0]);
      ::close(toChild[1]);
      return false;
    }
    pid_ = ::fork();
    if (pid_ < 0) return false;
    if (pid_ == 0) {
      // Its own process group, so a timeout kills the wrapper's children too; and it dies with us, so a
      // killed run leaves no engine behind.
      ::setpgid(0, 0);
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      ::dup2(toChild[0], STDIN_FILENO);
      ::dup2(fromChild[1], STDOUT_FILENO);
      ::close(toChild[0]);
      ::close(toChild[1]);
      ::close(fromChild[0]);
      ::close(fromChild[1]);
      ::execl("/bin/sh", "sh", "-c", command_.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(toChild[0]);
    ::close(fromChild[1]);
    toChild_ = toChild[1];
    fromChild_ = fromChild[0];
    buffer_.clear();
    return true;
  }

  void stop() {
    if (toChild_ >= 0) ::close(toChild_);
    if (fromChild_ >= 0) ::close(fromChild_);
    toChild_ = fromChild_ = -1;
    if (pid_ > 0) {
      ::kill(-pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
    pid_ = -1;
  }

  bool writeAll(const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(toChild_, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

  // One reply line within the timeout; the problem in words, or "" on success.
  std::string readLine(std::string& line) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options_.timeoutSeconds);
    for (;;) {
      if (const auto nl = buffer_.find('\n'); nl != std::string::npos) {
        line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return "";
      }
      if (buffer_.size() > options_.maxReplyBytes) {
        return "a reply longer than " + std::to_string(options_.maxReplyBytes) + " bytes";
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return "no reply within " + std::to_string(options_.timeoutSeconds) + " s (the engine hangs)";
      pollfd p{fromChild_, POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) continue;
      char chunk[65536];
      const ssize_t n = ::read(fromChild_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        int status = 0;
        ::waitpid(pid_, &status, 0);
        pid_ = -1;
        const std::string how = WIFSIGNALED(status) ? "was killed by signal " + std::to_string(WTERMSIG(status))
                                                    : "exited with status " + std::to_string(WEXITSTATUS(status));
        return "the engine process " + how + " before replying (it crashed)";
      }
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

  std::string command_;
  EngineOptions options_;
  pid_t pid_ = -1;
  int toChild_ = -1, fromChild_ = -1;
  std::string buffer_;
};

}  // namespace

std::unique_ptr<Engine> makeProcessEngine(const std::string& command, const EngineOptions& options) {
  return std::make_unique<ProcessEngine>(command, options);
}

}  // namespace cyclecert
