#include "harness/run/campaign.h"

namespace cyclecert {

using nlohmann::json;

namespace {

json member(const json& record, const std::string& field) {
  if (field == "shards") {  // N of "shard": "K/N"; none for an unsharded run
    if (!record.contains("shard") || !record["shard"].is_string()) return nullptr;
    const std::string shard = record["shard"].get<std::string>();
    const auto slash = shard.find('/');
    return slash == std::string::npos ? json(shard) : json(shard.substr(slash + 1));
  }
  return record.contains(field) ? record[field] : json(nullptr);
}

std::string valueText(const json& v) {
  if (v.is_null()) return "none";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

std::string text(const json& record, const char* field) { return valueText(member(record, field)); }

std::optional<CampaignDifference> firstDifference(const SourcedRecord& a, const SourcedRecord& b,
                                                  const std::vector<std::string>& fields) {
  for (const std::string& field : fields) {
    const json x = member(a.record, field), y = member(b.record, field);
    if (x != y) return CampaignDifference{field, valueText(x), valueText(y), a.source, b.source};
  }
  return std::nullopt;
}

// The fields two records to be joined must agree on (mergeDifference in campaign.h).
std::vector<std::string> mergedFields(const json& a, const json& b) {
  if (text(a, "command") != text(b, "command")) return {};
  // Runs of different engines fill different engines' parts of one report, which compares them.
  if (text(a, "engine") != text(b, "engine")) return {"spec_suite_hash"};
  if (text(a, "command") == "fuzz") {
    return {"engine_version", "vs", "seed", "formats", "cycles", "metamorphic", "shards", "spec_suite_hash"};
  }
  return {"engine_version", "metamorphic", "spec_suite_hash"};
}

}  // namespace

std::optional<CampaignDifference> resumeDifference(const std::vector<SourcedRecord>& existing, const SourcedRecord& next) {
  static const std::vector<std::string> sameCommand{"engine", "engine_version", "vs",          "seed",
                                                     "formats", "cycles",       "metamorphic", "shard", "spec_suite_hash"};
  static const std::vector<std::string> otherCommand{"engine", "engine_version"};
  for (const SourcedRecord& r : existing) {
    const bool same = text(r.record, "command") == text(next.record, "command");
    if (auto d = firstDifference(r, next, same ? sameCommand : otherCommand)) return d;
  }
  return std::nullopt;
}

std::optional<CampaignDifference> mergeDifference(const std::vector<std::vector<SourcedRecord>>& inputs) {
  std::vector<SourcedRecord> all, latestFuzz;  // latestFuzz: each input's last fuzz run
  for (const std::vector<SourcedRecord>& records : inputs) {
    const SourcedRecord* latest = nullptr;
    for (const SourcedRecord& r : records) {
      all.push_back(r);
      if (text(r.record, "command") == "fuzz") latest = &r;
    }
    if (latest) latestFuzz.push_back(*latest);
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (auto d = firstDifference(all[j], all[i], mergedFields(all[j].record, all[i].record))) return d;
    }
  }
  for (std::size_t i = 0; i < latestFuzz.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (text(latestFuzz[j].record, "engine") != text(latestFuzz[i].record, "engine")) continue;
      if (auto d = firstDifference(latestFuzz[j], latestFuzz[i], {"cases"})) return d;
    }
  }
  return std::nullopt;
}

std::string differenceText(const CampaignDifference& d) {
  const std::string name = d.field == "shards" ? "shard count" : d.field;
  // formats, cycles, metamorphic: absent in a record is the default (two-block; g71,g72; off)
  const auto value = [&](const std::string& v) {
    if (d.field == "metamorphic") return std::string(v == "none" ? "off" : "on");
    if (v != "none") return v;
    return d.field == "formats" ? std::string("two-block") : d.field == "cycles" ? std::string("g71,g72") : v;
  };
  return name + " " + value(d.first) + " in " + d.firstSource + ", " + value(d.second) + " in " + d.secondSource;
}

}  // namespace cyclecert
