#pragma once
// The results table of `multidir batch`: one row per model, written as CSV or JSON (docs/batch.md).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace multidir::cli {

struct BatchRow {
  std::string model;          // the model's path, as the batch listed it
  std::string status;         // "done", "done before" (a plan folder found complete) or "failed"
  long long faces = 0;
  double jgBeforeMm2 = 0.0;
  double jgAfterMm2 = 0.0;
  int regions = 0;
  double seconds = 0.0;       // wall time of the model's whole run: loading, search, supports, saving
  double peakMemoryMiB = 0.0; // the most resident memory during that run
  std::string error;          // why it failed; empty otherwise
};

// A row as JSON (also the record beside a finished plan, batch-row.json; a failed model's numbers are null) and
// back; rowFromJson throws nlohmann::json::exception for a record that is not one.
nlohmann::ordered_json rowToJson(const BatchRow& row);
BatchRow rowFromJson(const nlohmann::json& json);

// The table as CSV (a header line, then one line per row; fields with a comma, quote or line break quoted).
std::string tableCsv(const std::vector<BatchRow>& rows);

// Writes the table to `path` atomically: JSON when it ends in .json, else CSV. Throws FileError.
void writeTable(const std::string& path, const std::vector<BatchRow>& rows);

}  // namespace multidir::cli
