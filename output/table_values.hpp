#pragma once
/// @file
/// An optional number as the tables (CSV) and summary.json write it: empty / null when absent.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iga {

inline std::string table_number(std::optional<double> v, const char* format = "%.6e") {
  if (!v) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

inline nlohmann::json optional_json(std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

}  // namespace iga
