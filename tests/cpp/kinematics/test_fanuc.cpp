// The Fanuc and Haas dialects: the control's power-on state, least-increment input, Macro B, subprograms and
// the words that move a Fanuc or a Haas (Fanuc Series 0i-MODEL F Operator's Manual B-64604EN: "Custom macro",
// "Subprogram", "Canned cycle for drilling", "Reference position"; Haas Mill Operator's Manual: G187, G234,
// M97, M98, G04).
#include "kinematics/gcode.hpp"

#include "support/gcode_errors.hpp"
#include "support/mutation.hpp"
#include "support/reader_fuzz.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace hsm::kinematics;
using hsm::test::errorOf;

namespace {
ReaderOptions control(Dialect dialect, bool leastIncrement = false) {
  ReaderOptions options;
  options.conventions.dialect = dialect;
  options.conventions.powerOnCodes = "G0 G17 G90 G94 G21 G98";
  options.conventions.leastIncrementInput = leastIncrement;
  options.conventions.workOffset = Eigen::Vector3d(-300, -200, -400);
  options.conventions.smoothingTolerance = 0.02;
  return options;
}
const ReaderOptions kFanuc = control(Dialect::Fanuc, true);
const ReaderOptions kHaas = control(Dialect::Haas);

std::vector<double> column(const std::vector<Block>& blocks, int axis) {
  std::vector<double> out;
  for (const Block& b : blocks) out.push_back(b.end[axis]);
  return out;
}

double dwellOf(const std::string& program, const ReaderOptions& options) {
  std::istringstream stream(program);
  GcodeReader reader(stream, options);
  Block b;
  while (reader.next(b)) {
  }
  return reader.stats().dwellTime;
}
}  // namespace

// The control starts in its power-on modes (parameter 3402: G00, G90…): coordinates before any G word move.
TEST(FanucDialect, ThePowerOnStateIsTheMachinesAndALeaderBeforePercentIsSkipped) {
  const auto blocks = readProgram("=== Information listing ===\nCreated by: someone\n%\nO0001\nX10. Y5.\nG1 Z-1. F200\n%\n",
                                  kFanuc);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].motion, Motion::Rapid);
  EXPECT_EQ(blocks[0].end, Eigen::Vector3d(10, 5, 0));
  EXPECT_EQ(blocks[0].line, 5);
  EXPECT_EQ(errorOf("X10. Y5.\n").rfind("line 1: coordinates before any motion mode", 0), 0u);  // LinuxCNC's start
}

// Parameter 3401 DPI off: X100 is 100 least increments (0.001 mm, 0.0001 inch); with a point, millimetres.
// A variable's value is a length, as the control takes it; F and S are not scaled.
TEST(FanucDialect, NumbersWithoutAPointAreLeastIncrementsWhereTheMachineSaysSo) {
  const auto blocks = readProgram("G1 X100 Y100. Z-2500 F200\nG20 X100 Y1.\n#1=100\nG21 X#1\n", kFanuc);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_NEAR(blocks[0].end.x(), 0.1, 1e-12);
  EXPECT_NEAR(blocks[0].end.y(), 100.0, 1e-12);
  EXPECT_NEAR(blocks[0].end.z(), -2.5, 1e-12);
  EXPECT_NEAR(blocks[0].feed * 60.0, 200.0, 1e-9);
  EXPECT_NEAR(blocks[1].end.x(), 100 * 0.0001 * 25.4, 1e-12);
  EXPECT_NEAR(blocks[1].end.y(), 25.4, 1e-12);
  EXPECT_NEAR(blocks[2].end.x(), 100.0, 1e-12);
  EXPECT_NEAR(readProgram("G1 X100 F200\n", kHaas)[0].end.x(), 100.0, 1e-12);  // a Haas: whole millimetres
}

// G04: a Fanuc's P in ms and X in s; a Haas's P in s with a point and in ms without; cycles' P likewise.
TEST(FanucDialect, DwellsAreInTheControlsUnits) {
  EXPECT_DOUBLE_EQ(dwellOf("G4 P1500\nG4 X2.5\n", kFanuc), 4.0);
  EXPECT_DOUBLE_EQ(dwellOf("G4 P1.5\nG4 P250\n", kHaas), 1.75);
  EXPECT_DOUBLE_EQ(dwellOf("G0 Z5.\nG82 X1. Z-2. R1. P500 F100\nX2.\nG80\n", kFanuc), 1.0);
  EXPECT_DOUBLE_EQ(dwellOf("G0 Z5\nG4 P1.5\n", ReaderOptions{}), 1.5);  // LinuxCNC: seconds
}

// G28 goes through the point given (G91 Z0: where it is) to the reference position, machine zero; G53 moves
// in machine coordinates for its block. The machine file's work offset says where machine zero is.
TEST(FanucDialect, ReferenceReturnAndMachineCoordinatesUseTheWorkOffset) {
  const auto blocks = readProgram("G0 X10. Y10. Z5.\nG91 G28 Z0.\nG90 G53 X-100. Y-50.\nG28 X20. Y0.\n", kFanuc);
  ASSERT_EQ(blocks.size(), 5u);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(10, 10, 400));  // machine Z0 is 400 mm above the program's zero
  EXPECT_EQ(blocks[1].motion, Motion::Rapid);
  EXPECT_EQ(blocks[2].end, Eigen::Vector3d(200, 150, 400));
  EXPECT_EQ(blocks[3].end, Eigen::Vector3d(20, 0, 400));  // through the intermediate point
  EXPECT_EQ(blocks[4].end, Eigen::Vector3d(300, 200, 400));
}

// "Canned cycle for drilling": in G91, R is from the initial level and Z from R, X Y from the last hole; K (a
// Fanuc) or L (a Haas, LinuxCNC) repeats the hole; K0 stores the cycle only.
TEST(FanucDialect, CannedCyclesRepeatWithKOrLAndReadIncrementally) {
  const auto fanuc = readProgram("G0 X0. Y0. Z10.\nG91 G99 G81 X10. Z-5. R-2. K3 F100\nG80\n", kFanuc);
  std::vector<double> bottoms;
  for (const Block& b : fanuc)
    if (b.motion == Motion::Linear) bottoms.push_back(b.end.x());
  EXPECT_EQ(bottoms, (std::vector<double>{10, 20, 30}));
  for (const Block& b : fanuc)
    if (b.motion == Motion::Linear) EXPECT_DOUBLE_EQ(b.end.z(), 3.0);  // R at 10 - 2, bottom 5 below R
  const auto haas = readProgram("G0 X0 Y0 Z10\nG91 G81 X10 Z-5 R-2 L2 F100\n", kHaas);
  EXPECT_EQ(haas.back().end, Eigen::Vector3d(20, 0, 10));  // G98 at power-on: back to the initial level
  EXPECT_EQ(readProgram("G0 Z10.\nG81 X1. Z-5. R2. K0 F100\n", kFanuc).size(), 1u);  // the G0 only
  EXPECT_EQ(errorOf("G0 Z10.\nG81 X1. Z-5. R2. K2.5 F100\n", kFanuc).rfind("line 2: G81 K2.5: a cycle's repeat count", 0), 0u);
}

// Fanuc's reverse tapping, fine boring and back boring (G74, G76, G87) are timed as the moves they make.
TEST(FanucDialect, FanucsOtherCyclesMoveAsTheManualDraws) {
  const auto tap = readProgram("G0 X0. Y0. Z10.\nG98 G74 X5. Z-5. R2. F100\n", kFanuc);
  ASSERT_EQ(tap.size(), 6u);  // to Z10, over the hole, down to R, in, out at feed to R, up to the initial level
  EXPECT_EQ(tap[4].motion, Motion::Linear);
  EXPECT_DOUBLE_EQ(tap[4].end.z(), 2.0);
  const auto back = readProgram("G0 X0. Y0. Z10.\nG87 X5. Z-2. R-10. F100\n", kFanuc);  // R below Z: from the back
  ASSERT_EQ(back.size(), 5u);
  EXPECT_DOUBLE_EQ(back[2].end.z(), -10.0);
  EXPECT_EQ(back[3].motion, Motion::Linear);
  EXPECT_DOUBLE_EQ(back[3].end.z(), -2.0);
  EXPECT_DOUBLE_EQ(back[4].end.z(), 10.0);
}

// G05.1 Q1 (AI contour control), G08 P1 and a Haas's G187: corners rounded within E or the machine's
// tolerance; G05.1 Q0 back to plain cutting. G43.4 / G234 program the tool tip; G49 cancels it.
TEST(FanucDialect, LookAheadModesAndToolCentrePoint) {
  const auto fanuc = readProgram("G1 X1. F100\nG05.1 Q1\nX2.\nG05.1 Q0\nX3.\nG43.4 H1 Z5.\nG49 Z6.\n", kFanuc);
  ASSERT_EQ(fanuc.size(), 5u);
  EXPECT_EQ(fanuc[0].pathMode, PathMode::Continuous);
  EXPECT_EQ(fanuc[1].pathMode, PathMode::Rounding);
  EXPECT_DOUBLE_EQ(fanuc[1].tolerance, 0.02);
  EXPECT_EQ(fanuc[2].pathMode, PathMode::Continuous);
  const auto haas = readProgram("G187 P1 E0.05\nG1 X1 F100\nG187\nX2\nG234 H1 A10 Z5\nG49 A0 Z6\n", kHaas);
  ASSERT_EQ(haas.size(), 4u);
  EXPECT_DOUBLE_EQ(haas[0].tolerance, 0.05);
  EXPECT_DOUBLE_EQ(haas[1].tolerance, 0.02);
  EXPECT_TRUE(haas[2].toolTip);
  EXPECT_FALSE(haas[3].toolTip);
}

// "Custom macro": variables, expressions without brackets on the right of '=', a vacant variable (#0, a local
// never set) leaves its word out of the block and counts as 0 in arithmetic but not in EQ.
TEST(FanucMacro, VariablesExpressionsAndVacantValues) {
  const auto blocks = readProgram(
      "#1=2.\n#2=#1*3+1\n#100=SQRT[16]+ATAN[1]/[1]\nG1 X#2 Y#100 Z#5 F100\n#3=#0\n#4=#3+1\n"
      "IF [#3 EQ 0] GOTO 10\nG1 X#4\nN10 IF [#3 EQ #0] THEN #6=7\nG1 Y#6 X-#1\n",
      kFanuc);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_DOUBLE_EQ(blocks[0].end.x(), 7.0);
  EXPECT_DOUBLE_EQ(blocks[0].end.y(), 49.0);
  EXPECT_DOUBLE_EQ(blocks[0].end.z(), 0.0);  // Z#5 (vacant): no Z in the block
  EXPECT_DOUBLE_EQ(blocks[1].end.x(), 1.0);  // vacant + 1; and vacant EQ 0 is false, so no jump
  EXPECT_DOUBLE_EQ(blocks[2].end.y(), 7.0);
  EXPECT_DOUBLE_EQ(blocks[2].end.x(), -2.0);
}

TEST(FanucMacro, WhileLoopsAndJumps) {
  const auto blocks = readProgram(
      "#1=0\nWHILE [#1 LT 3] DO 1\n#2=0\nWHILE [#2 LT 2] DO 2\nG1 X[#1*10+#2] F100\n#2=#2+1\nEND 2\n#1=#1+1\nEND 1\n"
      "GOTO 20\nG1 X99.\nN20 G1 Y1.\n",
      kFanuc);
  EXPECT_EQ(column(blocks, 0), (std::vector<double>{1, 10, 11, 20, 21, 21}));  // X0 first: no move
  EXPECT_DOUBLE_EQ(blocks.back().end.y(), 1.0);
}

// "Subprogram": M98 P L calls a program of the same file (after M30) or of its own file; M99 returns, M99 P to
// a sequence number of the caller; a Fanuc 0's M98 P30100 is three calls of O0100. A Haas's M97 calls a
// sequence number of the program. G65 passes arguments as locals (A: #1, X: #24) in their own scope.
TEST(FanucMacro, SubprogramsAndMacroCalls) {
  const std::string subs = "O0100\nG91 G1 X1. F100\nG90\nM99\nO0200\nG1 Y#24 Z#1 F100\n#1=99\nM99\n%\n";
  auto fanuc = readProgram("%\nO0001\nG1 X0. F100\nM98 P100 L2\nM98 P20100\n#1=5\nG65 P200 X3. A-1.\nG1 X#1\nM30\n" + subs, kFanuc);
  EXPECT_EQ(column(fanuc, 0), (std::vector<double>{1, 2, 3, 4, 4, 5}));
  EXPECT_EQ(fanuc[4].end, Eigen::Vector3d(4, 3, -1));
  const auto haas = readProgram("%\nO01000\nG0 X0 Y0\nM97 P500 L2\nG0 X9\nM30\nN500 G91 G1 Y2 F100\nG90\nM99\n%\n", kHaas);
  EXPECT_EQ(column(haas, 1), (std::vector<double>{2, 4, 4}));
  const auto jump = readProgram("G1 X0. F100\nM98 P300\nX5.\nN40 X6.\nM30\nO0300\nG1 Y1.\nM99 P40\n", kFanuc);
  EXPECT_EQ(column(jump, 0), (std::vector<double>{0, 6}));  // M99 P40 comes back to N40, past X5.
}

TEST(FanucMacro, SubprogramFilesAreFoundBesideTheProgramAndAMissingOneIsNamed) {
  const auto folder = std::filesystem::temp_directory_path() / "hsm_fanuc_subs";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "O1234.nc") << "%\nO1234 (POCKET)\nG91 G1 X2. F100\nG90\nM99\n%\n";
  ReaderOptions options = kFanuc;
  options.subroutineFolders = {folder.string()};
  const auto blocks = readProgram("G1 X1. F100\nM98 P1234 L2\nG1 Y3.\nM30\n", options);
  EXPECT_EQ(column(blocks, 0), (std::vector<double>{1, 3, 5, 5}));
  const std::string missing = errorOf("M98 P4321\n", options);
  EXPECT_EQ(missing.rfind("line 1: subprogram O4321 is neither in the program nor in a file (looked for " +
                              (folder / "O4321.nc").string(), 0), 0u) << missing;
  std::filesystem::remove_all(folder);
}

// Bounded and named: an endless loop, an alarm, a jump to nowhere, a loop not closed, a call that never ends.
TEST(FanucMacro, WhatCannotRunIsNamedAndLoopsAreBounded) {
  ReaderOptions bounded = kFanuc;
  bounded.maxLoopIterations = 1000;
  EXPECT_EQ(errorOf("N1 G1 X1. F100\nGOTO 1\n", bounded).rfind("line 2: the program has jumped back to the same line 1000 times", 0), 0u);
  EXPECT_EQ(errorOf("#1=1\nWHILE [#1 GT 0] DO 1\nEND 1\n", bounded).rfind("line 3: WHILE ... DO 1 has turned 1000 times", 0), 0u);
  EXPECT_EQ(errorOf("#3000=12 (TOOL BROKEN)\n", kFanuc).rfind("line 1: the program raises alarm #3000 = 12", 0), 0u);
  EXPECT_EQ(errorOf("GOTO 55\n", kFanuc).rfind("line 1: N55 is not in this program", 0), 0u);
  EXPECT_EQ(errorOf("#1=#[#100]\n", kFanuc).rfind("line 1: #[...] names no parameter: its number is vacant", 0), 0u);
  EXPECT_EQ(errorOf("WHILE [1 EQ 0] DO 1\nG1 X1. F100\n", kFanuc).rfind("line 1: WHILE ... DO 1 has no END 1", 0), 0u);
  EXPECT_EQ(errorOf("END 2\n", kFanuc).rfind("line 1: END 2 without its WHILE", 0), 0u);
  EXPECT_EQ(errorOf("M98 P10\nM30\nO0010\nM98 P10\nM99\n", kFanuc).rfind("line 4: M98: calls nested more than 20 deep", 0), 0u);
  EXPECT_EQ(errorOf("#5221=10.\n", kFanuc).rfind("line 1: #5221 cannot be set here", 0), 0u);
  EXPECT_EQ(errorOf("#1=1/0\n", kFanuc).rfind("line 1: division by zero", 0), 0u);
  EXPECT_EQ(errorOf("G1 X[1e3] F100\n", kFanuc).rfind("line 1: a number with an exponent", 0), 0u);
  EXPECT_EQ(errorOf("#[-5]=1\n", kFanuc).rfind("line 1: #-5 is not a parameter: Fanuc's variables", 0), 0u);
  EXPECT_EQ(errorOf("G187 P1 E-5\n", kHaas).rfind("line 1: E-5: a smoothing tolerance is positive", 0), 0u);
  ReaderOptions moving = kFanuc;
  moving.conventions.powerOnCodes = "G1 X5 F100";
  EXPECT_THROW(readProgram("G1 X1.\n", moving), hsm::InputError);  // power-on codes that move are refused
  EXPECT_EQ(errorOf("G68.2 X0 Y0 Z0 I0 J45. K0\n", kFanuc).rfind("line 1: 'G68.2' (a rotated or tilted working plane", 0), 0u);
}

// M30 ends the main program: the subprograms after it run only when called. M99 in the main program (a Fanuc
// runs it again for ever) is timed as one pass.
TEST(FanucMacro, TheMainProgramEndsAtM30OrM99) {
  EXPECT_EQ(readProgram("G1 X1. F100\nM30\nO0100\nG1 X5.\nM99\n", kFanuc).size(), 1u);
  EXPECT_EQ(readProgram("G1 X1. F100\nG1 X2.\nM99\n", kFanuc).size(), 2u);
}

// G10 L2 sets a work offset, L20 so that the tool is at the value given; G92 shifts the coordinates.
TEST(FanucDialect, WorkOffsetsAndG92) {
  const auto blocks = readProgram(
      "G10 L2 P2 X-290. Y-200. Z-400.\nG0 G55 X0.\nG54 X0.\nG92 X100.\nX110.\nG92.1\nX0.\nG10 L20 P1 X5.\nX5.\nX6.\n", kFanuc);
  EXPECT_EQ(column(blocks, 0), (std::vector<double>{10, 0, 10, 0, 1}));  // L20: here is X5
  EXPECT_EQ(readProgram("G10 L1 P1 Z5. R2.\nG0 X1.\n", kFanuc).size(), 1u);  // tool data: counted, no move
  EXPECT_EQ(errorOf("G10 L3 P1 X5.\n", kFanuc).rfind("line 1: 'G10 L3' (an offset table", 0), 0u);  // G55 is 10 mm further in X; G92: here is 100
}

// Programs of other ISO dialects and templates a post left unfinished are refused in one line that says so.
TEST(FanucDialect, OtherIsoDialectsAndUnfinishedTemplatesAreNamed) {
  const std::string millplus = errorOf("%\nO0001 (PROGRAM)\nN0090 G54 I1\nN0100 G74 Z-.1 L1\n", kFanuc);
  EXPECT_EQ(millplus.rfind("line 3: this is a Heidenhain MillPlus program", 0), 0u) << millplus;
  const std::string okuma = errorOf("O0001 (PROGRAM)\nN0050 T01\nN0100 G56 Z4.3307 H01\n", kFanuc);
  EXPECT_EQ(okuma.rfind("line 3: this is an Okuma OSP program", 0), 0u) << okuma;
  const std::string unfinished = errorOf("%\nO ENTER OP AND LAST 3 DIGITS\nG0 X1.\n", kHaas);
  EXPECT_EQ(unfinished.rfind("line 2: 'O ENTER OP AND LAST 3 DI' is not a program number", 0), 0u) << unfinished;
  // G83 with Q0: one pass on a Fanuc (a post's "no peck"), refused by LinuxCNC's reading
  EXPECT_EQ(readProgram("G0 X0. Y0. Z5.\nG83 X1. Z-2. R1. Q0 F100\n", kFanuc).size(), 5u);
  EXPECT_EQ(errorOf("G0 X0 Y0 Z5\nG83 X1 Z-2 R1 Q0 F100\n").rfind("line 2: G83 needs Q > 0", 0), 0u);
}

// Mutations of a program using the whole Fanuc/Haas language are read or refused with an InputError, never a
// crash, a non-finite position or an endless run (loops bounded at 1000 turns).
TEST(FanucMacro, FuzzedProgramsAreReadOrRefusedNeverCrash) {
  const std::string seed =
      "%\nO0001\n#1=2.\n#100=#1*3+[SIN[30]]\nN10 G1 X#100 F100\nIF [#1 LT 4] THEN #1=#1+1\nIF [#1 LT 4] GOTO 10\n"
      "WHILE [#1 GT 0] DO 1\nG91 G81 X1. Z-2. R-1. K2\nG90 G80\n#1=#1-1\nEND 1\nM98 P100 L2\nG65 P200 A1. X2.\n"
      "M97 P300\nG91 G28 Z0.\nG05.1 Q1\nG43.4 H1 Z5.\nM30\nN300 G4 P100\nM99\nO0100\nG1 Y#0 Z-1.\nM99\n"
      "O0200\nG1 X#24 Y#1\nM99\n%\n";
  const std::string alphabet = "#[]=ONGXYZFKLPQRHAM0123456789.-+*/ \nIFWHILEDOENTGOTHabcdefghilnoprstuw%";
  ReaderOptions bounded;
  bounded.conventions.dialect = Dialect::Haas;
  bounded.conventions.powerOnCodes = "G0 G17 G90 G21 G98";
  bounded.maxLoopIterations = 1000;
  ASSERT_GT(readProgram(seed, bounded).size(), 10u);
  hsm::test::expectReadAndRefused(seed, alphabet, bounded, 11);
}
