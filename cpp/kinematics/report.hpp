// Reports of a simulation: the summary as JSON, blocks as CSV rows (feeds in mm/min, as people read them).
#pragma once

#include "kinematics/simulation.hpp"

#include <ostream>
#include <string>

namespace hsm::kinematics {

// JSON with total_time_s, cutting_time_s, rapid_time_s, naive_time_s, block_count, feed_classes, …
std::string summaryJson(const SimulationSummary& summary, const std::string& program = "");
std::string blockCsvHeader();
// G0, G1, G2 or G3: a block's motion as the program writes it.
const char* motionName(Motion motion);
// The header and one row per block.
std::string blocksCsv(const std::vector<BlockResult>& blocks);
void writeBlockCsv(std::ostream& out, const BlockResult& block);
std::string traceCsvHeader();
void writeTraceCsv(std::ostream& out, const TraceSample& sample);
// A few lines a person reads at the end of a run.
std::string summaryText(const SimulationSummary& summary);

}  // namespace hsm::kinematics
