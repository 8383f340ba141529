#pragma once
// converge.csv: one row per dynamic body and quantity, with its value in every run of the
// study, the relative changes, and the verdicts (columns: docs/convergence.md).
#include <filesystem>

#include "study/convergence_verdict.hpp"

namespace blockdem {

void write_convergence_csv(const std::filesystem::path& file, const ConvergenceResult& result);

}  // namespace blockdem
