#include "kinematics/report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hsm::kinematics {

const char* motionName(Motion m) {
  switch (m) {
    case Motion::Rapid: return "G0";
    case Motion::Linear: return "G1";
    case Motion::ArcClockwise: return "G2";
    case Motion::ArcCounterClockwise: return "G3";
  }
  return "?";
}

namespace {

std::vector<double> asVector(const std::array<double, 5>& values) { return {values.begin(), values.end()}; }

double limitTotal(const SimulationSummary& s) {
  double total = 0.0;
  for (double t : s.limitTime) total += t;
  return total;
}

nlohmann::json speedLimitsJson(const SimulationSummary& s) {
  nlohmann::json names = nlohmann::json::array(), times = nlohmann::json::array(), shares = nlohmann::json::array();
  const double total = limitTotal(s);
  for (int k = 0; k < kSpeedLimitCount; ++k) {
    names.push_back(speedLimitName(static_cast<SpeedLimit>(k)));
    times.push_back(s.limitTime[k]);
    shares.push_back(total > 0.0 ? s.limitTime[k] / total : 0.0);
  }
  return {{"names", names}, {"time_s", times}, {"share_of_time", shares}};
}
}  // namespace

std::string summaryJson(const SimulationSummary& s, const std::string& program) {
  using nlohmann::json;
  json unknown = json::object();
  for (const auto& [word, count] : s.reader.unknownWordCounts) unknown[word] = count;
  const json report = {
      {"program", program},
      {"machine", s.machine},
      {"total_time_s", s.totalTime},
      {"cutting_time_s", s.cuttingTime},
      {"rapid_time_s", s.rapidTime},
      {"dwell_time_s", s.dwellTime},
      {"naive_time_s", s.naiveTime},
      {"naive_cutting_time_s", s.naiveCuttingTime},
      {"time_over_naive", s.timeOverNaive()},
      {"block_count", s.blockCount},
      {"cutting_blocks", s.cuttingBlocks},
      {"rapid_blocks", s.rapidBlocks},
      {"cutting_length_mm", s.cuttingLength},
      {"rapid_length_mm", s.rapidLength},
      {"feed_classes",
       {{"edges_of_programmed_feed", kFeedClassEdges},
        {"labels", {"<0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", ">=0.9"}},
        {"share_of_blocks", asVector(s.feedClasses.blocks)},
        {"share_of_length", asVector(s.feedClasses.length)},
        {"share_of_time", asVector(s.feedClasses.time)}}},
      {"block_length_classes", {{"edges_mm", kLengthClassEdges}, {"cutting_blocks", s.lengthClasses}}},
      {"speed_limits", speedLimitsJson(s)},
      {"reader",
       {{"lines", s.reader.lines},
        {"motion_blocks", s.reader.motionBlocks},
        {"unknown_words", s.reader.unknownWords},
        {"unknown_word_counts", unknown},
        {"tool_changes", s.reader.toolChanges}}}};
  return report.dump(2);
}

std::string blocksCsv(const std::vector<BlockResult>& blocks) {
  std::ostringstream out;
  out << blockCsvHeader();
  for (const BlockResult& b : blocks) writeBlockCsv(out, b);
  return out.str();
}

std::string blockCsvHeader() {
  return "line,motion,x0,y0,z0,x1,y1,z1,length_mm,programmed_feed_mm_min,entry_feed_mm_min,exit_feed_mm_min,"
         "min_feed_mm_min,mean_feed_mm_min,peak_feed_mm_min,start_time_s,time_s,limit,"
         "rotary1_start_deg,rotary2_start_deg,rotary1_end_deg,rotary2_end_deg\n";
}

void writeBlockCsv(std::ostream& out, const BlockResult& b) {
  char row[512];
  std::snprintf(row, sizeof row,
                "%ld,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.5f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.6f,%.7f,%s,%.4f,%.4f,%.4f,%.4f\n",
                b.line, motionName(b.motion), b.start.x(), b.start.y(), b.start.z(), b.end.x(), b.end.y(), b.end.z(),
                b.length, b.programmedFeed * 60, b.entryFeed * 60, b.exitFeed * 60, b.minFeed * 60, b.meanFeed * 60,
                b.peakFeed * 60, b.startTime, b.time, speedLimitName(b.limit), b.rotaryStart[0], b.rotaryStart[1],
                b.rotaryEnd[0], b.rotaryEnd[1]);
  out << row;
}

std::string traceCsvHeader() { return "t_s,x_mm,y_mm,z_mm,feed_mm_min\n"; }

void writeTraceCsv(std::ostream& out, const TraceSample& s) {
  char row[160];
  std::snprintf(row, sizeof row, "%.4f,%.4f,%.4f,%.4f,%.1f\n", s.t, s.x, s.y, s.z, s.v * 60);
  out << row;
}

std::string summaryText(const SimulationSummary& s) {
  std::ostringstream text;
  char line[200];
  auto minutes = [](double seconds) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%d:%05.2f", int(seconds / 60), seconds - 60 * int(seconds / 60));
    return std::string(buffer);
  };
  std::snprintf(line, sizeof line, "machine %s: %ld blocks (%ld cutting, %ld rapid), %.1f mm cutting\n",
                s.machine.c_str(), s.blockCount, s.cuttingBlocks, s.rapidBlocks, s.cuttingLength);
  text << line;
  std::snprintf(line, sizeof line, "simulated time %s (cutting %s, rapid %s, dwell %s)\n", minutes(s.totalTime).c_str(),
                minutes(s.cuttingTime).c_str(), minutes(s.rapidTime).c_str(), minutes(s.dwellTime).c_str());
  text << line;
  std::snprintf(line, sizeof line, "length/feed estimate %s: the machine takes %.2f times as long\n",
                minutes(s.naiveTime).c_str(), s.timeOverNaive());
  text << line;
  text << "reached / programmed feed, share of cutting time:";
  const char* labels[] = {"<0.3", "0.3-0.5", "0.5-0.7", "0.7-0.9", ">=0.9"};
  for (int k = 0; k < 5; ++k) {
    std::snprintf(line, sizeof line, "  %s %.1f%%", labels[k], 100 * s.feedClasses.time[k]);
    text << line;
  }
  text << "\n";
  // What held the speed, largest share first: "C 18.0 %" tells a 5-axis user which axis to look at.
  const double total = limitTotal(s);
  if (total > 0.0) {
    std::vector<int> order(kSpeedLimitCount);
    for (int k = 0; k < kSpeedLimitCount; ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return s.limitTime[a] > s.limitTime[b]; });
    text << "speed held by, share of time:";
    for (int k : order)
      if (s.limitTime[k] > 0.0005 * total) {
        std::snprintf(line, sizeof line, "  %s %.1f%%", speedLimitName(static_cast<SpeedLimit>(k)),
                      100 * s.limitTime[k] / total);
        text << line;
      }
    text << "\n";
  }
  if (s.reader.unknownWords > 0) {  // named, the most frequent first: what the time leaves out
    std::vector<std::pair<std::string, long>> words(s.reader.unknownWordCounts.begin(), s.reader.unknownWordCounts.end());
    std::stable_sort(words.begin(), words.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    text << s.reader.unknownWords << " unknown words skipped:";
    for (size_t i = 0; i < words.size() && i < 8; ++i) text << (i ? ", " : " ") << words[i].first << " x" << words[i].second;
    text << (words.size() > 8 ? ", ...\n" : "\n");
  }
  return text.str();
}

}  // namespace hsm::kinematics
