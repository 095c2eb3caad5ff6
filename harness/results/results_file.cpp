#include "harness/results/results_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/io/input_file.h"
#include "harness/judge/judging.h"

namespace cyclecert {

namespace {

std::string dumped(const nlohmann::json& j) {
  // An engine's reply may hold anything (a process engine's message); the line must stay JSON.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// README "Limits": a result line holds at most kMaxInputBytes, what the readers take
// (readBoundedLine). A longer one leaves out, in turn, the failure's plot, the findings' witnesses,
// the findings after the first ten, and cuts the detail and the program to their first 4 KiB —
// each named in "left_out" — so that a path of a million failing moves still gives a result.
std::string boundedLine(nlohmann::json& j) {
  std::string text = dumped(j);
  if (text.size() <= kMaxInputBytes) return text;
  nlohmann::json leftOut = nlohmann::json::array();
  const auto note = [&](const std::string& what) {
    leftOut.push_back(what);
    j["left_out"] = leftOut;
    text = dumped(j);
    return text.size() <= kMaxInputBytes;
  };
  if (j.contains("plot")) {
    j.erase("plot");
    if (note("the plot")) return text;
  }
  for (auto& f : j["findings"]) f.erase("witness");
  if (note("the findings' witnesses")) return text;
  if (j["findings"].size() > 10) {
    const std::size_t all = j["findings"].size();
    j["findings"].erase(j["findings"].begin() + 10, j["findings"].end());
    if (note("findings 11 to " + std::to_string(all))) return text;
  }
  constexpr std::size_t kKept = 4096;
  for (const char* field : {"detail", "program"}) {
    if (j.contains(field) && j[field].is_string() && j[field].get_ref<const std::string&>().size() > kKept) {
      j[field] = j[field].get<std::string>().substr(0, kKept);
    }
  }
  note("the detail and the program after their first 4 KiB");
  return text;
}

}  // namespace

std::string resultLine(const CaseResult& r) {
  // Field by field, not from an initializer list (which builds each pair as an array first): a
  // line is written for every case a fuzz run judges.
  nlohmann::json j = nlohmann::json::object();
  j["engine"] = r.engine;
  j["case"] = r.caseId;
  j["file"] = r.file;
  j["rules"] = r.rules;
  j["verdict"] = r.verdict;
  j["detail"] = r.detail;
  j["findings"] = findingsJson(r.findings);
  j["seconds"] = r.seconds;
  j["seed"] = r.seed ? nlohmann::json(*r.seed) : nlohmann::json(nullptr);
  if (!r.program.empty()) j["program"] = r.program;
  if (!r.vs.empty()) j["vs"] = r.vs;
  if (r.plot) j["plot"] = *r.plot;
  if (!r.reproduce.empty()) j["reproduce"] = r.reproduce;
  if (r.expectation) {
    j["expectation"] = {{"status", r.expectation->status}};
    if (!r.expectation->reason.empty()) j["expectation"]["reason"] = r.expectation->reason;
    if (!r.expectation->source.empty()) j["expectation"]["source"] = r.expectation->source;
  }
  return boundedLine(j) + "\n";
}

ResultLines readResultLines(const std::string& file) {
  ResultLines out;
  std::ifstream in(file);
  std::string line;
  for (BoundedLine read; (read = readBoundedLine(in, line)) != BoundedLine::End;) {
    if (read == BoundedLine::TooLong) {  // no result line is written so long (resultLine)
      ++out.skipped;
      continue;
    }
    try {
      const auto j = nlohmann::json::parse(line);
      out.lines.push_back({line, {j.at("engine").get<std::string>(), j.at("case").get<std::string>()}});
    } catch (const std::exception&) {  // not JSON, or not a result
      ++out.skipped;
    }
  }
  return out;
}

namespace {

std::string safeText(std::size_t safe) {
  return safe == 1 ? "1 result is safe" : std::to_string(safe) + " results are safe";
}

// All of `bytes` to `fd`, or the errno that stopped it.
int writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

int openForAppend(const std::string& path, int extraFlags) {
  // O_CLOEXEC: an engine's process must not inherit the file.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | extraFlags, 0644);
  if (fd < 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  return fd;
}

// The complete lines kept by a resumed run, written to a new file that then replaces the old one:
// a failure leaves the old file as it was.
void rewriteKept(const std::string& path, const std::vector<ResultLines::Line>& kept) {
  const std::string partial = path + ".partial";
  const int fd = openForAppend(partial, O_TRUNC);
  std::string text;
  for (const ResultLines::Line& line : kept) text += line.text + "\n";
  const int error = writeAll(fd, text);
  ::close(fd);
  if (error != 0) {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
    throw ResultsWriteError("cannot write '" + partial + "': " + std::strerror(error) + "; nothing was run: " +
                                safeText(kept.size()) + " in '" + path + "', unchanged",
                            kept.size());
  }
  std::filesystem::rename(partial, path);
}

}  // namespace

ResultsFile::ResultsFile(const std::string& outDir, bool resume) : path_(outDir + "/results.jsonl") {
  std::filesystem::create_directories(outDir);
  const std::filesystem::file_status status = std::filesystem::status(path_);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw std::runtime_error("cannot write '" + path_ + "': it is not a regular file; remove it or give another --out");
  }
  if (resume) {
    const std::vector<ResultLines::Line> kept = readResultLines(path_).lines;
    for (const ResultLines::Line& line : kept) done_.insert(line.key);
    rewriteKept(path_, kept);
    safe_ = kept.size();
  }
  fd_ = openForAppend(path_, resume ? 0 : O_TRUNC);
}

ResultsFile::~ResultsFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsFile::append(const CaseResult& r) { write(resultLine(r)); }

void ResultsFile::appendLine(const std::string& jsonLine) { write(jsonLine + "\n"); }

void ResultsFile::write(const std::string& bytes) {
  if (const int error = writeAll(fd_, bytes)) {
    throw ResultsWriteError("cannot write '" + path_ + "': " + std::strerror(error) + "; stopped: " +
                                safeText(safe_) + " in it (a last line cut short is skipped by --resume, " +
                                "merge and report)",
                            safe_);
  }
  ++safe_;
}

}  // namespace cyclecert
