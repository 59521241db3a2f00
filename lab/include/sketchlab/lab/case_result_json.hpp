#pragma once
// The record of one finished case, <case>/case_result.json: what the run
// needs of the case to write metrics.csv, metrics.json and the report
// without running it again (ok, error, metrics, relations, per-stroke
// latencies, wall time). `sketchlab run --resume` keeps the cases that have
// one; ranks of a distributed run send it to rank 0. Doubles are written in
// shortest round-trip form (a metric that is not finite as null), so a
// record read back gives the same bytes in every file made from it.
#include <filesystem>
#include <string>
#include <string_view>

#include "sketchlab/lab/experiment_runner.hpp"

namespace sketchlab {

// The file name inside a case's folder.
inline constexpr const char* case_result_file = "case_result.json";

std::string case_result_to_json(const CaseResult& result);

// Reads the fields case_result_to_json writes into `result` (recording,
// variant and dir are left as they are). Throws std::runtime_error
// "<name>: <field>: <reason>" on anything else.
void case_result_from_json(std::string_view text, const std::string& name, CaseResult& result);

}  // namespace sketchlab
