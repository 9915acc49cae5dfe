#include "batch_table.h"

#include <cstdio>

#include "cli_args.h"
#include "multidir/core/common/atomic_file.h"

namespace multidir::cli {
namespace {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

nlohmann::ordered_json rowToJson(const BatchRow& row) {
  const bool failed = row.status == "failed";
  auto measured = [&](auto value) { return failed ? nlohmann::ordered_json() : nlohmann::ordered_json(value); };
  return {{"model", row.model},
          {"status", row.status},
          {"faces", measured(row.faces)},
          {"jg_before_mm2", measured(row.jgBeforeMm2)},
          {"jg_after_mm2", measured(row.jgAfterMm2)},
          {"regions", measured(row.regions)},
          {"seconds", row.seconds},
          {"peak_memory_mib", row.peakMemoryMiB},
          {"error", row.error}};
}

BatchRow rowFromJson(const nlohmann::json& json) {
  auto measured = [&](const char* key, auto zero) {
    const nlohmann::json& value = json.at(key);
    return value.is_null() ? zero : value.get<decltype(zero)>();
  };
  BatchRow row;
  row.model = json.at("model").get<std::string>();
  row.status = json.at("status").get<std::string>();
  row.faces = measured("faces", 0LL);
  row.jgBeforeMm2 = measured("jg_before_mm2", 0.0);
  row.jgAfterMm2 = measured("jg_after_mm2", 0.0);
  row.regions = measured("regions", 0);
  row.seconds = json.at("seconds").get<double>();
  row.peakMemoryMiB = json.at("peak_memory_mib").get<double>();
  row.error = json.at("error").get<std::string>();
  return row;
}

std::string tableCsv(const std::vector<BatchRow>& rows) {
  std::string csv = "model,status,faces,jg_before_mm2,jg_after_mm2,regions,seconds,peak_memory_mib,error\n";
  for (const BatchRow& row : rows) {
    const bool failed = row.status == "failed";
    csv += csvField(row.model) + "," + csvField(row.status) + "," + (failed ? "" : std::to_string(row.faces)) + "," +
           (failed ? "" : number("%.9g", row.jgBeforeMm2)) + "," + (failed ? "" : number("%.9g", row.jgAfterMm2)) + "," +
           (failed ? "" : std::to_string(row.regions)) + "," + number("%.3f", row.seconds) + "," +
           number("%.1f", row.peakMemoryMiB) + "," + csvField(row.error) + "\n";
  }
  return csv;
}

void writeTable(const std::string& path, const std::vector<BatchRow>& rows) {
  std::string text;
  if (endsWith(path, ".json")) {
    nlohmann::ordered_json table = nlohmann::ordered_json::array();
    for (const BatchRow& row : rows) table.push_back(rowToJson(row));
    text = table.dump(2) + "\n";
  } else {
    text = tableCsv(rows);
  }
  if (const core::Status written = core::writeTextFileAtomically(path, text); !written)
    throw FileError("multidir batch: cannot write the table " + path + ": " + written.error().describe());
}

}  // namespace multidir::cli
