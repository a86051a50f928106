// hsm-feedsim: simulate what a machine really does on a G-code program.
//
//   hsm-feedsim PROGRAM --machine NAME_OR_FILE [--json OUT] [--csv OUT] [--trace OUT [--trace-period S]]
//   hsm-feedsim PROGRAM --machine NAME_OR_FILE --moves OUT     (the moves as read, nothing simulated)
#include "kinematics/gcode.hpp"
#include "kinematics/report.hpp"
#include "kinematics/simulation.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <unistd.h>

using namespace hsm::kinematics;

namespace {

std::vector<std::string> machineFolders() {
  std::vector<std::string> folders;
  if (const char* env = std::getenv("HSM_MACHINES_DIR")) folders.push_back(env);
  folders.push_back(HSM_MACHINES_DIR);
  return folders;
}

// The moves as the reader makes them of the program (before the planner merges any): what LinuxCNC's rs274
// prints as canonical moves, to compare with it (tests/oracle/compare_rs274.py).
void writeMoves(std::istream& program, const ReaderOptions& reading, std::ostream& out) {
  out << "line,motion,x,y,z,centre_x,centre_y,centre_z,feed_mm_min,rotary_1,rotary_2,rotary_3\n";
  GcodeReader reader(program, reading);
  Block b;
  char row[400];
  while (reader.next(b)) {
    std::snprintf(row, sizeof row, "%ld,%s,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.6f,%.6f,%.6f\n", b.line,
                  motionName(b.motion),
                  b.end.x(), b.end.y(), b.end.z(), b.center.x(), b.center.y(), b.center.z(), b.feed * 60.0,
                  b.rotaryEnd.x(), b.rotaryEnd.y(), b.rotaryEnd.z());
    out << row;
  }
}

// A progress bar on the terminal, from the share of the file read.
class Progress {
public:
  Progress(std::ifstream& file, bool show) : file_(file), show_(show && isatty(STDERR_FILENO)) {
    file_.seekg(0, std::ios::end);
    size_ = static_cast<double>(file_.tellg());
    file_.seekg(0);
  }
  void update(long line) {
    if (!show_ || size_ <= 0) return;
    const double share = std::min(1.0, static_cast<double>(file_.tellg()) / size_);
    const int filled = static_cast<int>(40 * share);
    std::fprintf(stderr, "\r[%s%s] %3d%%  line %ld", std::string(filled, '#').c_str(),
                 std::string(40 - filled, ' ').c_str(), static_cast<int>(100 * share), line);
    drawn_ = true;
  }
  void done() {
    if (drawn_) std::fprintf(stderr, "\r%s\r", std::string(70, ' ').c_str());
  }

private:
  std::ifstream& file_;
  bool show_, drawn_ = false;
  double size_ = 0.0;
};

std::ofstream openOutput(const std::string& path, const char* what) {
  std::ofstream out(path);
  if (!out) throw hsm::InputError("cannot write the " + std::string(what) + " file '" + path + "': check the folder");
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Simulate the feed rate a machine really reaches on a G-code program (HSM Planner)"};
  std::string program, machineName, jsonPath, csvPath, tracePath, movesPath;
  std::vector<std::string> subroutineFolders;
  double tracePeriod = 0.004;
  bool refuseUnknown = false, skipUnknown = false, quiet = false, listMachines = false;
  app.add_option("program", program, "G-code file in the machine's dialect (LinuxCNC, grbl, Fanuc, Haas or Siemens 840D)");
  app.add_option("--machine,-m", machineName, "machine name (see --list-machines) or machine JSON file");
  app.add_option("--json", jsonPath, "write the summary as JSON");
  app.add_option("--csv", csvPath, "write one row per block as CSV (feeds in mm/min)");
  app.add_option("--moves", movesPath, "write the moves as read (end, arc centre, feed) as CSV and simulate nothing");
  app.add_option("--trace", tracePath, "write a time-sampled trace t,x,y,z,feed as CSV");
  app.add_option("--trace-period", tracePeriod, "seconds between trace samples")->check(CLI::PositiveNumber);
  app.add_option("--subroutines", subroutineFolders,
                 "folder of LinuxCNC subroutine files (NAME.ngc for o<name> call), after the program's own; repeatable");
  app.add_flag("--refuse-unknown", refuseUnknown, "stop at the first word the reader does not understand");
  app.add_flag("--skip-unknown", skipUnknown,
               "skip and count a word that would move the machine but is not understood (by default it stops the "
               "reading at its line)");
  app.add_flag("--quiet,-q", quiet, "no progress bar and no summary on the terminal");
  app.add_flag("--list-machines", listMachines, "list the machine models found and exit");
  CLI11_PARSE(app, argc, argv);

  try {
    if (listMachines) {
      for (const auto& name : machineNames(machineFolders())) std::cout << name << "\n";
      return 0;
    }
    if (program.empty()) throw hsm::InputError("no program given: hsm-feedsim PROGRAM --machine NAME");
    if (machineName.empty()) throw hsm::InputError("no machine given: add --machine NAME (see --list-machines)");
    const MachineModel machine = loadMachine(machineName, machineFolders());
    std::ifstream file(program, std::ios::binary);
    if (!file) throw hsm::InputError("cannot read the program '" + program + "': check the path");

    std::ofstream csv, trace;
    SimulationOptions options;
    if (!csvPath.empty()) {
      csv = openOutput(csvPath, "CSV");
      csv << blockCsvHeader();
      options.onBlock = [&](const BlockResult& b) { writeBlockCsv(csv, b); };
    }
    if (!tracePath.empty()) {
      trace = openOutput(tracePath, "trace");
      trace << traceCsvHeader();
      options.tracePeriod = tracePeriod;
      options.onTraceSample = [&](const TraceSample& s) { writeTraceCsv(trace, s); };
    }
    std::ofstream json;
    if (!jsonPath.empty()) json = openOutput(jsonPath, "JSON");
    Progress progress(file, !quiet);
    options.onProgress = [&](long line) { progress.update(line); };
    ReaderOptions reading;
    reading.refuseUnknownWords = refuseUnknown;
    const size_t slash = program.find_last_of('/');  // subroutine files beside the program first, as LinuxCNC
    reading.subroutineFolders.push_back(slash == std::string::npos ? "." : program.substr(0, slash));
    reading.subroutineFolders.insert(reading.subroutineFolders.end(), subroutineFolders.begin(), subroutineFolders.end());
    reading.skipUnknownMotion = skipUnknown;
    reading.conventions = machine.conventions;
    if (!movesPath.empty()) {
      std::ofstream moves = openOutput(movesPath, "moves");
      writeMoves(file, reading, moves);
      return 0;
    }
    const SimulationResult result = simulate(file, machine, reading, options);
    progress.done();
    if (json.is_open()) json << summaryJson(result.summary, program) << "\n";
    if (!quiet) std::cout << summaryText(result.summary);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "hsm-feedsim: error: " << error.what() << "\n";
    return 1;
  }
}
