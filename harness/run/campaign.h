#pragma once
// Which runs are one campaign, from their run.json records (run_record.h): results of different
// campaigns — another seed, engine, fuzz --formats, number of cases, shard split or spec suite — must not be mixed
// in one results.jsonl without a word, for the report would count them as one. `--resume` and
// `merge` check it (and `--mix-campaigns` lets them mix on purpose).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cyclecert {

// A run record and where it comes from ("OUT/run.json", "this run"), for messages.
struct SourcedRecord {
  nlohmann::json record;
  std::string source;
};

// The first field on which two records differ, with both values as text ("none" when absent).
struct CampaignDifference {
  std::string field;  // run.json's name: "seed", "engine", "cases", "shard", "spec_suite_hash", …
  std::string first, second;
  std::string firstSource, secondSource;
};

// Continuing a run: the new record must match each record of the same command already in OUT on
// the engines and their versions, the seed, the fuzz --formats, the shard and the spec suite — not on --cases: case i
// of a seed is the same case whatever the number of cases, so a resumed run may extend the
// campaign. A fuzz run may resume a check run (or the other way round) of the same engine and
// version: the two fill different parts of one engine's report.
std::optional<CampaignDifference> resumeDifference(const std::vector<SourcedRecord>& existing,
                                                   const SourcedRecord& next);

// Joining runs, given each input's records in order: one engine's fuzz runs must be shards of one
// campaign (same engine version, vs, seed, --formats, number of shards, spec suite, and the inputs' latest
// runs the same --cases); one engine's check runs its version and the spec suite. Runs of different
// engines (make run's report: check and fuzz of reference and linuxcnc) must share the spec suite
// only: they fill different engines' parts of one report, which compares them. A check run and a
// fuzz run fill different parts of a report and are not compared.
std::optional<CampaignDifference> mergeDifference(const std::vector<std::vector<SourcedRecord>>& inputs);

// "seed 7 in A/run.json, 8 in B/run.json".
std::string differenceText(const CampaignDifference& d);

struct CampaignMismatchError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The flag that mixes campaigns knowingly, for the messages.
inline constexpr const char* kMixCampaignsFlag = "--mix-campaigns";

}  // namespace cyclecert
