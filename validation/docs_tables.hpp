// The Markdown tables of docs/validation.md, made from the records of validation/record.hpp:
// one summary row per record and, per record, its heading line and its tables of numbers.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace valsalva::validation {

// A Markdown table cell: '|' escaped, line breaks as spaces.
std::string md_cell(const std::string& text);
void write_md_table(std::ostream& out, const std::vector<std::string>& columns,
                    const std::vector<std::vector<std::string>>& rows);

// A number as the tables print it (6 significant digits; "not finite" for null).
std::string format_number(const nlohmann::ordered_json& value);
// What a metric must satisfy: "5.58 +- 0.01", "<= 0.01", ">= 1.8".
std::string metric_target(const nlohmann::ordered_json& metric);

// The summary row of a record: {metric, measured, reference / target, result, date}. For a
// measured record the metric shown is the first that fails, else the one with the least room
// left to its bound; the result counts the metrics that pass.
std::vector<std::string> summary_cells(const nlohmann::ordered_json& record);

// "Full level" / "Quick level": where the numbers come from, then the tables.
void write_record_results(std::ostream& out, const nlohmann::ordered_json& record);

}  // namespace valsalva::validation
