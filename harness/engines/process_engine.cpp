// process:COMMAND — any program speaking JSON lines (README "The process protocol"): one request
// per line on its stdin — the spec case with "request": N added, N a number that grows with every
// request — and one reply per line on its stdout, echoing "request": N, with one of
// {"toolpath": {…}}, {"alarm": {"code", "message", "line"}}, {"not_applicable": "…"} or {"error": "…"}.
//
// The process is started once and reused. Everything that goes wrong is an engine failure of the
// case it happens in, the process is restarted (its whole process group killed) so the next case
// starts in sync, and the run goes on:
// - no reply within the timeout (which covers writing the request as well as reading the reply),
// - the process ended (crashed) or closed its stdout while running,
// - a line that is not the reply to the current request (not JSON, no or another "request"),
// - more output after the reply (a second reply, a log line) in the same read or already waiting,
// - a reply beyond the size cap, or one that is not a valid toolpath/alarm.
// Output that was not yet there when the reply was taken is found before the next request is
// written (it is waiting on the pipe), or while that request waits (a second reply to the previous
// request): it is never taken as the next case's reply. runBatch then turns the previous case's
// result into that engine failure; run() has already returned it, so it restarts the engine and
// runs the next case on the fresh process.
#include <chrono>
#include <optional>

#include "harness/engines/engines.h"
#include "harness/engines/process_reply.h"
#include "harness/engines/subprocess.h"

namespace cyclecert {

namespace {

// At most this much of an unexpected line in a message.
constexpr std::size_t kQuotedBytes = 200;

std::string quotedLine(const std::string& text) {
  std::string shown = text.substr(0, kQuotedBytes);
  for (char& ch : shown) {
    if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
  }
  return "'" + shown + (text.size() > kQuotedBytes ? "…' (" + std::to_string(text.size()) + " bytes)" : "'");
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One exchange: the case's result, and what it showed about the previous case's (extra output
// that came after that case's result was taken).
struct Exchange {
  EngineResult result;
  std::optional<std::string> previousCaseFault;
};

class ProcessEngine : public Engine {
 public:
  ProcessEngine(std::string command, const EngineOptions& options) : command_(std::move(command)), options_(options) {}

  std::string name() const override { return "process:" + command_; }
  std::string description() const override { return "external engine `" + command_ + "` (JSON lines)"; }
  std::string version() const override { return command_; }

  EngineResult run(const SpecCase& c) override { return exchange(c).result; }

  std::vector<EngineResult> runBatch(const std::vector<SpecCase>& cases) override {
    std::vector<EngineResult> results;
    results.reserve(cases.size());
    for (const SpecCase& c : cases) {
      Exchange x = exchange(c);
      if (x.previousCaseFault && !results.empty()) {
        const double seconds = results.back().seconds;
        results.back() = EngineResult::failed(*x.previousCaseFault);
        results.back().seconds = seconds;
      }
      results.push_back(std::move(x.result));
    }
    return results;
  }

 private:
  Exchange exchange(const SpecCase& c) {
    const auto started = std::chrono::steady_clock::now();
    Exchange x;
    if (process_) {
      if (const std::string late = process_->readWaiting(kQuotedBytes + 1); !late.empty()) {
        x.previousCaseFault = "after its reply, the engine wrote more: " + quotedLine(late);
        stop();
      }
    }
    std::optional<EngineResult> result = ask(c, x);
    if (!result) result = ask(c, x);  // a second reply to the previous case came: again, in sync
    x.result = result ? std::move(*result) : EngineResult::failed("the engine replied to an earlier request twice");
    x.result.seconds = secondsSince(started);
    return x;
  }

  // The request for `c` and its reply. A second reply to the previous request, seen while waiting,
  // goes to x.previousCaseFault and gives nothing: the process is stopped, the caller asks again.
  std::optional<EngineResult> ask(const SpecCase& c, Exchange& x) {
    if (!process_) {
      try {
        process_.emplace(SubprocessSpec{{"/bin/sh", "-c", command_}, std::nullopt, "", true, false});
      } catch (const std::exception& e) {
        return EngineResult::failed("cannot start `" + command_ + "`: " + e.what());
      }
      buffer_.clear();
      scanned_ = 0;
      answered_ = 0;
    }
    const long request = ++requests_;
    nlohmann::json message = c.raw;
    message["request"] = request;
    const Deadline deadline = deadlineAfter(options_.timeoutSeconds);
    switch (process_->write(message.dump() + "\n", deadline)) {
      case IoResult::Done: break;
      case IoResult::Closed: return restartAfter("the engine stopped reading its input: " + howItEnded());
      case IoResult::TimedOut:
        return restartAfter("the engine did not read the case within " + timeout() + " s (its input is full)");
    }
    std::string line;
    if (const std::string problem = readLine(line, deadline); !problem.empty()) return restartAfter(problem);
    nlohmann::json reply;
    try {
      reply = parseProcessReply(line, request);
    } catch (const std::exception& e) {
      return restartAfter("invalid JSON reply to request " + std::to_string(request) + ": " + quotedLine(line) + " (" +
                          e.what() + ")");
    }
    const nlohmann::json* echoed = reply.is_object() && reply.contains("request") ? &reply["request"] : nullptr;
    if (echoed && answered_ > 0 && *echoed == answered_) {
      x.previousCaseFault = "the engine replied twice to this case: the second reply was " + quotedLine(line);
      stop();
      return std::nullopt;
    }
    if (!echoed || *echoed != request) {
      return restartAfter("a line that is not the reply to request " + std::to_string(request) + ": " + quotedLine(line) +
                          " (expected a JSON object with \"request\": " + std::to_string(request) + ")");
    }
    std::string more = buffer_;
    if (more.size() <= kQuotedBytes) more += process_->readWaiting(kQuotedBytes + 1 - more.size());
    if (!more.empty()) return restartAfter("after its reply, the engine wrote more: " + quotedLine(more));
    answered_ = request;
    return processReplyResult(reply);
  }

  // One line within the deadline; the problem in words, or "" on success.
  std::string readLine(std::string& line, Deadline deadline) {
    for (;;) {
      if (const auto nl = buffer_.find('\n', scanned_); nl != std::string::npos) {
        line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        scanned_ = 0;
        return "";
      }
      scanned_ = buffer_.size();
      if (buffer_.size() > options_.maxReplyBytes) {
        return "a reply longer than " + std::to_string(options_.maxReplyBytes) + " bytes";
      }
      switch (process_->read(buffer_, nullptr, deadline)) {
        case IoResult::Done: break;
        case IoResult::TimedOut: return "no reply within " + timeout() + " s (the engine hangs)";
        case IoResult::Closed: return outputClosed();
      }
    }
  }

  // Its stdout is at its end: it ended (crashed), or it closed its output and runs on.
  std::string outputClosed() {
    if (const auto status = process_->endedBy(deadlineAfter(kEndGraceSeconds))) {
      return "the engine process " + status->describe() + " before replying (it crashed)";
    }
    return "the engine closed its output (its stdout) but is still running";
  }

  std::string howItEnded() {
    const auto status = process_->endedBy(deadlineAfter(kEndGraceSeconds));
    return status ? "it " + status->describe() : "it closed its stdin but is still running";
  }

  std::string timeout() const {
    std::string s = std::to_string(options_.timeoutSeconds);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  }

  EngineResult restartAfter(const std::string& problem) {
    stop();
    return EngineResult::failed(problem);
  }

  void stop() { process_.reset(); }

  // How long a process whose output ended may take to exit before it counts as still running.
  static constexpr double kEndGraceSeconds = 0.5;

  std::string command_;
  EngineOptions options_;
  std::optional<Subprocess> process_;
  long requests_ = 0;       // the last request's number
  long answered_ = 0;       // the last request the running process answered (0: none yet)
  std::string buffer_;      // what it wrote beyond the last line taken
  std::size_t scanned_ = 0; // buffer_ holds no newline before this
};

}  // namespace

std::unique_ptr<Engine> makeProcessEngine(const std::string& command, const EngineOptions& options) {
  return std::make_unique<ProcessEngine>(command, options);
}

}  // namespace cyclecert
