// Fuzz harness of the G-code reader and the feed-rate simulator: any program text on every machine
// preset. A finding is a crash, a sanitizer report, an exception that is not one of the core's
// (InputError / ComputationError, which name the line and the fix), or a non-finite or negative time.
#include "kinematics/simulation.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {
const std::vector<hsm::kinematics::MachineModel>& machines() {
  static const std::vector<hsm::kinematics::MachineModel> models = [] {
    std::vector<hsm::kinematics::MachineModel> list;
    for (const std::string& name : hsm::kinematics::machineNames({HSM_MACHINES_DIR}))
      list.push_back(hsm::kinematics::loadMachine(name, {HSM_MACHINES_DIR}));
    return list;
  }();
  return models;
}

void finding(const char* what) {
  std::fprintf(stderr, "fuzz_gcode finding: %s\n", what);
  std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const auto& machine : machines()) {
    for (bool perSecond : {false, true}) {
      std::istringstream program(text);
      hsm::kinematics::ReaderOptions reading;
      reading.feedInMmPerSecond = perSecond;
      reading.maxLoopIterations = 1000;  // a loop of the LinuxCNC language that never ends stops soon
      try {
        const auto result = hsm::kinematics::simulate(program, machine, reading);
        const auto& s = result.summary;
        for (double t : {s.totalTime, s.cuttingTime, s.rapidTime, s.dwellTime, s.naiveTime})
          if (!std::isfinite(t) || t < 0.0) finding("a time of the summary is not a finite non-negative number");
        if (!std::isfinite(s.cuttingLength) || !std::isfinite(s.rapidLength)) finding("a length is not finite");
      } catch (const hsm::InputError&) {
      } catch (const hsm::ComputationError&) {
      } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        finding("an exception that is not one of the core's");
      }
    }
  }
  return 0;
}
