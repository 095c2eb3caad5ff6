#include "harness/run/run_record.h"

#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "cyclecert_git_revision.h"
#include "cyclecert_version.h"
#include "harness/io/input_file.h"
#include "harness/run/campaign.h"
#include "harness/spec/spec_suite_hash.h"

namespace cyclecert {

using nlohmann::json;

std::string utcNowIso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

RunRecord startRunRecord(const std::string& command, const Engine& engine, const Engine* vs, const std::string& specsDir,
                         std::optional<std::uint64_t> seed, std::vector<std::string> argv) {
  RunRecord r;
  r.command = command;
  r.engine = engine.name();
  r.engineVersion = engine.version();
  if (vs) r.vs = vs->name();
  r.cyclecertVersion = CYCLECERT_VERSION;
  r.gitRevision = CYCLECERT_GIT_REVISION;
  r.specSuiteHash = specSuiteHash(specsDir);
  r.started = utcNowIso8601();
  r.seed = seed;
  r.argv = std::move(argv);
  return r;
}

json runRecordJson(const RunRecord& r) {
  json j{{"command", r.command},
         {"engine", r.engine},
         {"engine_version", r.engineVersion},
         {"cyclecert_version", r.cyclecertVersion},
         {"git_revision", r.gitRevision},
         {"spec_suite_hash", r.specSuiteHash},
         {"started", r.started},
         {"argv", r.argv}};
  if (!r.vs.empty()) j["vs"] = r.vs;
  if (r.seed) j["seed"] = *r.seed;
  if (r.cases) j["cases"] = *r.cases;
  if (!r.shard.empty()) j["shard"] = r.shard;
  if (!r.formats.empty()) j["formats"] = r.formats;  // absent: the default, as in records written before --formats
  if (!r.cycles.empty()) j["cycles"] = r.cycles;     // absent: the default (g71,g72), as before --cycles
  if (r.metamorphic) j["metamorphic"] = true;        // absent: without the relations, as before --metamorphic
  return j;
}

std::vector<json> readRunRecords(const std::string& outDir) {
  const std::string file = outDir + "/run.json";
  if (!std::filesystem::exists(file)) return {};
  json j;
  try {
    j = json::parse(readInputFile(file));
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("runs") || !j["runs"].is_array()) {
    throw std::runtime_error(file + ": expected {\"runs\": [...]}");
  }
  std::vector<json> runs;
  for (std::size_t i = 0; i < j["runs"].size(); ++i) {
    const json& run = j["runs"][i];
    if (!run.is_object() || !run.contains("engine") || !run["engine"].is_string()) {
      throw std::runtime_error(file + ": /runs/" + std::to_string(i) + ": expected a run record with its \"engine\"");
    }
    runs.push_back(run);
  }
  return runs;
}

void writeRunRecords(const std::string& outDir, const std::vector<json>& runs) {
  std::filesystem::create_directories(outDir);
  const std::string file = outDir + "/run.json";
  const std::string partial = file + ".partial";
  {
    std::ofstream out(partial, std::ios::trunc);
    out << json{{"runs", runs}}.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
    out.close();  // the last of the text is written here, and may fail here
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(partial, ignored);
      throw std::runtime_error("cannot write " + partial + " (disk full?); " + file + " is unchanged");
    }
  }
  std::filesystem::rename(partial, file);
}

namespace {

// A resumed run must continue the campaign the records in OUT are of.
void checkSameCampaign(const std::string& outDir, const std::vector<json>& runs, const json& next) {
  std::vector<SourcedRecord> existing;
  for (const json& run : runs) existing.push_back({run, outDir + "/run.json"});
  const auto d = resumeDifference(existing, {next, "this run"});
  if (!d) return;
  std::string hint = "resume with the same options";
  if (d->field == "seed" && d->first != "none") hint += " (--seed " + d->first + ")";
  if (d->field == "formats") hint += " (--formats " + (d->first == "none" ? std::string("two-block") : d->first) + ")";
  if (d->field == "cycles") hint += " (--cycles " + (d->first == "none" ? std::string("g71,g72") : d->first) + ")";
  if (d->field == "metamorphic") hint += d->first == "none" ? " (without --metamorphic)" : " (with --metamorphic)";
  throw CampaignMismatchError("cannot resume the run in '" + outDir + "': this run is of another campaign: " +
                              differenceText(*d) + "; " + hint + ", write to another --out, or give " +
                              kMixCampaignsFlag + " to mix the two in one report knowingly");
}

}  // namespace

void recordRun(const std::string& outDir, const RunRecord& r, bool append, bool mixCampaigns) {
  std::vector<json> runs = append ? readRunRecords(outDir) : std::vector<json>{};
  const json next = runRecordJson(r);
  if (append && !mixCampaigns) checkSameCampaign(outDir, runs, next);
  runs.push_back(next);
  writeRunRecords(outDir, runs);
}

}  // namespace cyclecert
