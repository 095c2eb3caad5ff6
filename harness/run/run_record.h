#pragma once
// OUT/run.json (reports/README.md): one record per run that wrote into OUT/results.jsonl — which
// command, engine and versions, the source revision and spec suite, when, the seed and the command
// line — so that a report can say what it certifies. A fresh run starts the file, --resume appends
// a record, `merge` joins the inputs' records.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/engines/engine.h"

namespace cyclecert {

struct RunRecord {
  std::string command;  // "check" | "fuzz"
  std::string engine, engineVersion, vs;  // vs: "" when none
  std::string cyclecertVersion, gitRevision, specSuiteHash;
  std::string started;  // ISO-8601 UTC
  std::optional<std::uint64_t> seed;
  std::optional<long> cases;  // fuzz: the campaign's --cases (none with --time alone)
  std::string shard;          // fuzz: "K/N" with --shard, else ""
  std::string formats;        // fuzz: --formats when not the default (two-block), else "": another campaign
  std::string cycles;         // fuzz: --cycles when not the default (g71,g72), else "": another campaign
  bool metamorphic = false;   // --metamorphic: the relations judged the cases too — another campaign
  std::vector<std::string> argv;
};

// A record of a run starting now.
RunRecord startRunRecord(const std::string& command, const Engine& engine, const Engine* vs, const std::string& specsDir,
                         std::optional<std::uint64_t> seed, std::vector<std::string> argv);

nlohmann::json runRecordJson(const RunRecord& r);

// The records of OUT/run.json; none when the file does not exist. Throws std::runtime_error naming
// the file when it is not a run file (or not a regular file, or over input_file.h's cap).
std::vector<nlohmann::json> readRunRecords(const std::string& outDir);

// Replaces OUT/run.json with these records (written to a temporary file and renamed, so a killed
// run never leaves half a file; a failed write throws and leaves the old file).
void writeRunRecords(const std::string& outDir, const std::vector<nlohmann::json>& runs);

// The run's record into OUT/run.json: after the records there with `append` (--resume), else alone.
// A run appended to records of another campaign (campaign.h) throws CampaignMismatchError naming
// the field that differs, unless `mixCampaigns`.
void recordRun(const std::string& outDir, const RunRecord& r, bool append, bool mixCampaigns = false);

std::string utcNowIso8601();  // "2025-01-31T12:34:56Z"

}  // namespace cyclecert
