#include "reports/html/report_fields.h"

namespace cyclecert::html {

namespace {
const nlohmann::json kNull;
const nlohmann::json kEmptyArray = nlohmann::json::array();
}  // namespace

const nlohmann::json& member(const nlohmann::json& j, std::string_view key) {
  if (!j.is_object()) return kNull;
  const auto it = j.find(key);
  return it == j.end() ? kNull : *it;
}

const nlohmann::json& listMember(const nlohmann::json& j, std::string_view key) {
  const nlohmann::json& m = member(j, key);
  return m.is_array() ? m : kEmptyArray;
}

std::string scalarText(const nlohmann::json& value, std::string_view fallback) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number() || value.is_boolean()) return value.dump();
  return std::string(fallback);
}

std::string textMember(const nlohmann::json& j, std::string_view key, std::string_view fallback) {
  return scalarText(member(j, key), fallback);
}

std::uint64_t countMember(const nlohmann::json& j, std::string_view key) {
  const nlohmann::json& m = member(j, key);
  if (m.is_number_unsigned()) return m.get<std::uint64_t>();
  if (m.is_number_integer()) return m.get<std::int64_t>() < 0 ? 0 : m.get<std::uint64_t>();
  return 0;
}

}  // namespace cyclecert::html
