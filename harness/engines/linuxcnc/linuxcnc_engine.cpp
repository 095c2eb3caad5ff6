// The `linuxcnc` engine: translate (linuxcnc_translate.cpp), run `rs274 -g` in a private HOME with
// an empty tool table, under a timeout and an output cap, and read its canonical calls back
// (linuxcnc_canon.cpp).
//
//   cd PRIVATE && env -i HOME=PRIVATE PATH=/usr/bin:/bin LC_ALL=C
//       LD_LIBRARY_PATH=BUILD/linuxcnc/usr/lib:BUILD/linuxcnc/usr/lib/x86_64-linux-gnu
//       BUILD/linuxcnc/usr/bin/rs274 -g -t PRIVATE/tool.tbl PRIVATE/case.ngc
#include "harness/engines/linuxcnc/linuxcnc_engine.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/engines/subprocess.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

namespace fs = std::filesystem;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// The shared-library folders of the extracted tree (as fetch-rs274.sh's wrapper sets them).
std::string libraryPath(const fs::path& root) {
  std::vector<std::string> dirs;
  std::error_code ec;
  if (fs::is_directory(root / "usr/lib", ec)) dirs.push_back((root / "usr/lib").string());
  for (const fs::path& base : {root / "usr/lib", root / "lib"}) {
    if (!fs::is_directory(base, ec)) continue;
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(base, ec)) {
      if (e.is_directory() && e.path().filename().string().find("-linux-gnu") != std::string::npos) {
        found.push_back(e.path().string());
      }
    }
    std::sort(found.begin(), found.end());
    dirs.insert(dirs.end(), found.begin(), found.end());
  }
  std::string joined;
  for (const std::string& d : dirs) joined += (joined.empty() ? "" : ":") + d;
  return joined;
}

EngineResult alarmed(Toolpath path, Alarm alarm) {
  EngineResult r;
  r.kind = EngineResult::Alarmed;
  path.alarm = std::move(alarm);
  r.path = std::move(path);
  return r;
}

// rs274's output for one case → the engine's result.
EngineResult interpret(const SpecCase& c, const LinuxCncProgram& p, const std::string& out, const std::string& err,
                       int exitCode) {
  CanonicalParse parse = parseCanonical(out);
  if (!parse.error.empty()) return EngineResult::failed("garbage output: " + parse.error);
  Toolpath& path = parse.path;
  path.profile = profileNameOrDefault(c.profile);
  path.plane = p.plane;
  if (exitCode != 0) {
    if (!parse.sawCycle) path.start = p.start;
    return alarmed(std::move(path), linuxCncAlarm(err, p.lines));
  }
  if (!parse.sawCycle || !parse.sawEnd) {
    return EngineResult::failed("rs274 ended (exit 0) before the end of the translated program");
  }
  if (!nearlyEqual(path.start, p.start, 1e-4)) {
    return EngineResult::failed("rs274 was not at the cycle start point when the cycle began");
  }
  path.start = p.start;
  path.warnings = p.warnings;
  CycleRecord cycle = p.cycle;
  cycle.firstMove = 0;
  cycle.moveCount = static_cast<std::size_t>(
      std::count_if(path.moves.begin(), path.moves.end(), [](const Move& m) { return m.phase != MovePhase::Return; }));
  path.cycles.push_back(std::move(cycle));
  return EngineResult::planned(std::move(path));
}

std::string seconds(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

std::string signalName(int sig) {
  const char* s = strsignal(sig);
  return s ? s : "unknown";
}

}  // namespace

LinuxCncEngine::LinuxCncEngine(std::string buildDir, LinuxCncOptions options)
    : buildDir_(std::move(buildDir)), root_((fs::path(buildDir_) / "linuxcnc").string()), options_(options) {}

LinuxCncEngine::~LinuxCncEngine() {
  if (!dir_.empty()) {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
}

std::string LinuxCncEngine::description() const {
  return "LinuxCNC's rs274 (Debian linuxcnc-uspace) on the case translated to G71.1/G72.1 (O-sub shape, G7); "
         "fetched by harness/engines/linuxcnc/fetch-rs274.sh";
}

std::string LinuxCncEngine::version() const {
  std::ifstream in(fs::path(root_) / "VERSION");
  std::string v;
  if (in && std::getline(in, v) && !v.empty()) return "linuxcnc-uspace " + v;
  return "linuxcnc-uspace (not fetched)";
}

std::string LinuxCncEngine::rs274Path() const { return (fs::path(root_) / "usr/bin/rs274").string(); }

bool LinuxCncEngine::available() const { return ::access(rs274Path().c_str(), X_OK) == 0; }

std::string LinuxCncEngine::privateDir() {
  if (dir_.empty()) {
    std::string tmpl = (fs::temp_directory_path() / "cyclecert-linuxcnc-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error(std::string("mkdtemp: ") + std::strerror(errno));
    dir_ = tmpl;
  }
  return dir_;
}

LinuxCncEngine::Output LinuxCncEngine::runRs274(const std::string& programText, double timeoutSeconds,
                                                std::size_t outputCap) {
  Output o;
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path dir = privateDir();
  const std::string tools = (dir / "tool.tbl").string(), ngc = (dir / "case.ngc").string();
  writeFile(tools, "");  // an empty tool table for every process
  std::error_code ec;
  fs::remove(dir / ".tool.mmap", ec);  // rs274's tool data lives in $HOME/.tool.mmap
  writeFile(ngc, programText);

  const std::string exe = rs274Path();
  std::vector<std::string> args = {exe, "-g", "-t", tools, ngc};
  std::vector<std::string> env = {"HOME=" + dir.string(), "LD_LIBRARY_PATH=" + libraryPath(root_), "PATH=/usr/bin:/bin",
                                  "LC_ALL=C"};
  // rs274 starts an embedded Python 3.11: its modules come from the tree when fetch-rs274.sh had to
  // fetch libpython3.11 (and -minimal) because this machine has none.
  if (fs::is_directory(fs::path(root_) / "usr/lib/python3.11/encodings", ec)) {
    env.push_back("PYTHONHOME=" + (fs::path(root_) / "usr").string());
  }
  SubprocessSpec spec;
  spec.argv = std::move(args);
  spec.environment = std::move(env);
  spec.workingDirectory = dir.string();
  spec.stdinPipe = false;  // /dev/null
  spec.stderrPipe = true;
  Subprocess rs274(spec);
  ++processes_;

  const Deadline deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     std::chrono::duration<double>(timeoutSeconds));
  for (;;) {
    const IoResult r = rs274.read(o.out, &o.err, deadline);
    if (r == IoResult::Closed) break;
    if (r == IoResult::TimedOut) {
      o.timedOut = true;
      break;
    }
    if (o.out.size() + o.err.size() > outputCap) {
      o.overCap = true;
      break;
    }
  }
  // Both outputs closed: it is ending (one that lingers past the deadline has timed out).
  if (!o.timedOut && !o.overCap && !rs274.endedBy(deadline)) o.timedOut = true;
  const ExitStatus status = rs274.kill();
  o.exitCode = status.exitCode;
  o.signal = status.signal;
  o.seconds = secondsSince(t0);
  return o;
}

EngineResult LinuxCncEngine::run(const SpecCase& c) {
  const auto t0 = std::chrono::steady_clock::now();
  EngineResult r = runBatch({c}).front();
  r.seconds = secondsSince(t0);
  return r;
}

std::vector<EngineResult> LinuxCncEngine::runBatch(const std::vector<SpecCase>& cases) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<EngineResult> results(cases.size());
  std::vector<std::optional<LinuxCncProgram>> programs(cases.size());
  std::vector<std::size_t> pending;  // cases to run, in order
  for (std::size_t i = 0; i < cases.size(); ++i) {
    LinuxCncTranslation t = translateForLinuxCnc(cases[i], options_, static_cast<int>(100 + i));
    if (!t.program) {
      results[i] = EngineResult::notApplicable(t.notApplicable);
      continue;
    }
    if (!available()) {
      results[i] = EngineResult::failed("rs274 not found at " + rs274Path() +
                                        ": run harness/engines/linuxcnc/fetch-rs274.sh " + buildDir_);
      continue;
    }
    programs[i] = std::move(t.program);
    pending.push_back(i);
  }

  const std::string caseMark = "cyclecert: case ";
  while (!pending.empty()) {
    // One program: each case's translation after a marker naming it, M2 once at the end.
    std::string text;
    for (std::size_t i : pending) {
      std::string body = programs[i]->text;
      const std::string end = "M2\n";
      if (body.size() >= end.size() && body.compare(body.size() - end.size(), end.size(), end) == 0) {
        body.resize(body.size() - end.size());
      }
      text += "(" + caseMark + std::to_string(i) + ")\n" + body;
    }
    text += "M2\n";
    // A batch gets a little more time per case, and the output cap of up to 64 cases.
    const double timeout = options_.timeoutSeconds + (pending.size() > 1 ? 0.05 * static_cast<double>(pending.size()) : 0);
    const std::size_t cap = options_.outputCap * std::min<std::size_t>(pending.size(), 64);
    Output o;
    try {
      o = runRs274(text, timeout, cap);
    } catch (const std::exception& e) {
      for (std::size_t i : pending) results[i] = EngineResult::failed(std::string("cannot run rs274: ") + e.what());
      break;
    }

    // Split stdout at the case markers.
    std::map<std::size_t, std::string> chunks;
    std::vector<std::size_t> order;
    {
      std::istringstream in(o.out);
      std::string line;
      std::optional<std::size_t> current;
      const std::string needle = "COMMENT(\"" + caseMark;
      while (std::getline(in, line)) {
        if (const auto at = line.find(needle); at != std::string::npos) {
          current = static_cast<std::size_t>(std::strtoul(line.c_str() + at + needle.size(), nullptr, 10));
          order.push_back(*current);
          continue;
        }
        if (current) chunks[*current] += line + '\n';
      }
    }
    std::vector<std::size_t> again;
    // A batch that times out stopped in the case that had begun last: the batch's time allows each
    // case its own timeout beyond what the cases before it took, so that case hung. It gets the
    // timeout at once (running it alone would cost the timeout again) and the cases after it run on
    // in a new batch.
    const bool hungInBatch = o.timedOut && pending.size() > 1 && !order.empty();
    const bool processFailed =
        !hungInBatch && (o.timedOut || o.overCap || o.signal != 0 || (o.exitCode != 0 && order.empty()));
    for (std::size_t k = 0; k < pending.size(); ++k) {
      const std::size_t i = pending[k];
      const bool reached = std::find(order.begin(), order.end(), i) != order.end();
      const bool last = !order.empty() && order.back() == i;
      if (hungInBatch && last) {
        results[i] = EngineResult::failed("rs274 timed out after " + seconds(options_.timeoutSeconds) +
                                          " s (in a batch: this case was running when it expired)");
      } else if (reached && !last) {
        results[i] = interpret(cases[i], *programs[i], chunks[i], "", 0);  // finished: a later case began
      } else if (last && !processFailed) {
        results[i] = interpret(cases[i], *programs[i], chunks[i], o.exitCode == 0 ? "" : o.err, o.exitCode);
      } else if (pending.size() > 1) {
        again.push_back(i);  // after the case rs274 stopped in, or the whole process failed: run again
      } else if (o.timedOut) {
        results[i] = EngineResult::failed("rs274 timed out after " + seconds(timeout) + " s");
      } else if (o.overCap) {
        results[i] = EngineResult::failed("rs274 printed more than " + std::to_string(cap) + " bytes");
      } else if (o.signal != 0) {
        results[i] = EngineResult::failed("rs274 crashed: signal " + std::to_string(o.signal) + " (" +
                                          signalName(o.signal) + ")");
      } else {
        results[i] = EngineResult::failed("rs274 exited with " + std::to_string(o.exitCode) +
                                          " before the case began: " + o.err.substr(0, 400));
      }
    }
    if (processFailed && pending.size() > 1) {
      // Find the guilty case: every unfinished case on its own.
      for (std::size_t i : again) results[i] = runBatch({cases[i]}).front();
      again.clear();
    }
    pending = std::move(again);
  }
  const double each = cases.empty() ? 0 : secondsSince(t0) / static_cast<double>(cases.size());
  for (EngineResult& r : results) r.seconds = each;
  return results;
}

std::unique_ptr<Engine> makeLinuxCncEngine(const std::string& buildDir) {
  return std::make_unique<LinuxCncEngine>(buildDir);
}

std::unique_ptr<Engine> makeLinuxCncEngine(const std::string& buildDir, const EngineOptions& options) {
  LinuxCncOptions o;
  o.timeoutSeconds = options.timeoutSeconds;
  o.outputCap = options.maxReplyBytes;
  return std::make_unique<LinuxCncEngine>(buildDir, o);
}

}  // namespace cyclecert
