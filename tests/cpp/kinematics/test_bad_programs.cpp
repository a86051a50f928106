// Programs and machines that once were misread, ran unbounded or gave non-finite times: each
// is a line-numbered error that names the word, or a finite simulation.
#include "kinematics/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <streambuf>
#include <string>

using namespace hsm;
using namespace hsm::kinematics;

namespace {
MachineModel preset(const std::string& name) { return loadMachine(name, {HSM_MACHINES_DIR}); }

std::string readError(const std::string& program) {
  try {
    readProgram(program);
  } catch (const ParseError& error) {
    return error.what();
  }
  return "no error";
}

// An endless stream of one character, counting what was read: a "file" without a line end.
class EndlessLine : public std::streambuf {
public:
  size_t served = 0;

protected:
  int_type underflow() override {
    chunk_.assign(1 << 16, 'X');
    setg(chunk_.data(), chunk_.data(), chunk_.data() + chunk_.size());
    served += chunk_.size();
    return traits_type::to_int_type('X');
  }

private:
  std::string chunk_;
};
}  // namespace

TEST(BadPrograms, NumbersThatAreNotGcodeNumbersAreLineNumberedErrors) {
  const std::pair<const char*, const char*> cases[] = {
      // the reader quotes the words upper-cased, as it reads them
      {"G1 X1 F100\nG1 X1e400\n", "line 2: 'X1E400': G-code numbers have no exponent"},
      {"G1 X0 F100\nG1 Y nan\nG1 X5\n", "line 2: 'Y NAN' is not a letter followed by a number"},
      {"G1 X inf F100\n", "line 1: 'X INF' is not a letter followed by a number"},
      {"G1 X-inf F100\n", "line 1: 'X-INF' is not a letter followed by a number"},
      {"G1 X12345678901 F100\n", "line 1: 'X12345678901' is out of range"},
      {"G1 X1 F100\nG2\n", "line 2: G2 without an end point or a centre"},
      {"G4 P-5\n", "line 1: G4 P-5: a dwell lasts 0 s or more"},
      {"G1 X1 F0\n", "line 1: a feed move at F0 (set at line 1)"},
      {"G1 X1 F100\nG0 F0 Z5\nG1 X2\n", "line 3: a feed move at F0 (set at line 2)"},
      {"G1 X1 F100\nR1=1e5\n", "line 2: 'R1=1E5': G-code numbers have no exponent"},
  };
  for (const auto& [program, expected] : cases) EXPECT_EQ(readError(program).rfind(expected, 0), 0u) << readError(program);
}

// FreeCAD CAM's area operations (Profile, Pocket Shape) end with `G0 F0.000000 Z…`: legal, as LinuxCNC reads it,
// as long as no feed move follows before another F.
TEST(BadPrograms, AnF0OnARapidIsRead) {
  EXPECT_EQ(readError("G1 X1 F100\nG0 F0.000000 Z5\nG1 X2 F200\n"), "no error");
  EXPECT_EQ(readError("G21 G90\nG0 F0 X0 Y0 Z5\n"), "no error");
}

TEST(BadPrograms, BinaryGarbageGivesAPrintableMessage) {
  const std::string message = readError(std::string("G1 X1 F100\n\x01\xff\xfe garbage\n"));
  EXPECT_EQ(message.rfind("line 2: unexpected character '\\x01' (byte 1)", 0), 0u) << message;
  for (const char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7F) << message;
}

TEST(BadPrograms, ALineWithoutEndIsRefusedAtOnceWithoutReadingTheFile) {
  EndlessLine endless;
  std::istream program(&endless);
  GcodeReader reader(program);
  Block block;
  try {
    reader.next(block);
    ADD_FAILURE() << "no error";
  } catch (const ParseError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("line 1: the line is longer than 65536 characters", 0), 0u) << error.what();
  }
  EXPECT_LE(endless.served, size_t(4) << 20) << "read far more than one line's worth";
}

TEST(BadPrograms, LongButFiniteCoordinatesGiveFiniteTimes) {
  const std::string program = "G0 X0 Y0 Z0\nG1 X999999999. Y-999999999. Z999999999. F1\nG0 X0\nM30\n";
  for (const std::string& name : machineNames({HSM_MACHINES_DIR})) {
    std::istringstream stream(program);
    const SimulationResult result = simulate(stream, preset(name));
    EXPECT_TRUE(std::isfinite(result.summary.totalTime)) << name;
    EXPECT_GT(result.summary.totalTime, 1e9) << name;  // 1.7e9 mm at 1 mm/min
  }
}

TEST(BadPrograms, TracePeriodsAndTraceSizeAreBounded) {
  const std::string program = "G1 X10 F6000\nG1 X0\nG1 X10\nG1 X0\nG1 X10\nG1 X0\nM30\n";
  SimulationOptions options;
  for (double period : {1e-9, -1.0, std::nan("")}) {
    options.tracePeriod = period;
    std::istringstream stream(program);
    EXPECT_THROW(simulate(stream, preset("linuxcnc-2.9"), {}, options), InputError) << period;
  }
  options.tracePeriod = 1e-3;
  std::istringstream stream(program);
  EXPECT_GT(simulate(stream, preset("linuxcnc-2.9"), {}, options).trace.size(), 100u);
}

TEST(BadPrograms, MachineFieldsSetOutOfRangeAreRefusedByName) {
  MachineModel machine = preset("mikron-ucp710-840d");
  machine.maxAcceleration.x() = 0.0;
  std::istringstream stream("G1 X10 F100\n");
  try {
    simulate(stream, machine);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("max acceleration of axis X"), std::string::npos) << error.what();
  }
  machine = preset("grbl");
  machine.arcTolerance = 1e-30;  // would cut an arc into chords for ever
  std::istringstream arc("G1 X10 F100\nG2 X-10 Y0 R10\n");
  EXPECT_THROW(simulate(arc, machine), InputError);
}
