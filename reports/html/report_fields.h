#pragma once
// Lenient reading of report.json for the HTML writer: the document is meant to follow
// reports/README.md, but a page for people must still be drawn (with "—" where a value is missing)
// when a hand-made or older report lacks a field, never abort half-way.
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cyclecert::html {

// j[key] when j is an object holding key, else a null value.
const nlohmann::json& member(const nlohmann::json& j, std::string_view key);
// j[key] when it is an array, else an empty array (so callers can always iterate).
const nlohmann::json& listMember(const nlohmann::json& j, std::string_view key);
// A string as is, a number or boolean as JSON writes it (a 64-bit seed keeps every digit), anything
// else (missing, null, object) as `fallback`.
std::string textMember(const nlohmann::json& j, std::string_view key, std::string_view fallback = "");
std::string scalarText(const nlohmann::json& value, std::string_view fallback = "");
// A non-negative integer count, 0 when missing or not a number.
std::uint64_t countMember(const nlohmann::json& j, std::string_view key);

}  // namespace cyclecert::html
