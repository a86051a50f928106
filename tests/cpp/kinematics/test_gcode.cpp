#include "kinematics/gcode.hpp"
#include "kinematics/gcode_lexer.hpp"

#include "support/gcode_errors.hpp"
#include "support/mutation.hpp"
#include "support/reader_fuzz.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace hsm::kinematics;
using hsm::test::errorOf;

namespace {
}  // namespace

TEST(Gcode, LinesFeedsAndModalState) {
  const auto blocks = readProgram(
      "%\n(FreeCAD post)\nG21 G90 G17\nG0 Z5.000\nG0 X10 Y20\nG1 Z-1 F600\nX20 ; modal G1\nG91 Y5\r\nG90\n"
      "G1 X20 Y25 Z-1\n%\n");
  ASSERT_EQ(blocks.size(), 5u);  // the last G1 goes nowhere
  EXPECT_EQ(blocks[0].motion, Motion::Rapid);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(10, 20, 5));
  EXPECT_EQ(blocks[2].motion, Motion::Linear);
  EXPECT_DOUBLE_EQ(blocks[2].feed, 10.0);  // 600 mm/min
  EXPECT_EQ(blocks[3].end, Eigen::Vector3d(20, 20, -1));
  EXPECT_EQ(blocks[4].end, Eigen::Vector3d(20, 25, -1));
  EXPECT_EQ(blocks[4].line, 8);
}

TEST(Gcode, InchesAndFreeCadFeedsInMmPerSecond) {
  EXPECT_DOUBLE_EQ(readProgram("G70 G1 X1 F10\nG71 X1\n")[1].end.x(), 1.0);  // 840D: G70 inch, G71 mm
  const auto inch = readProgram("G20\nG1 X1 F10\n");
  EXPECT_DOUBLE_EQ(inch[0].end.x(), 25.4);
  EXPECT_DOUBLE_EQ(inch[0].feed, 254.0 / 60.0);
  // LinuxCNC sets F before the line's G20 ("order of execution"; rs274 shows it): from G21, `G20 F10` is 10 mm/min
  const auto sameLine = readProgram("G20 G1 X1 F10\n");
  EXPECT_DOUBLE_EQ(sameLine[0].end.x(), 25.4);
  EXPECT_DOUBLE_EQ(sameLine[0].feed, 10.0 / 60.0);
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  EXPECT_DOUBLE_EQ(readProgram("G700 G1 X1 F10\n", siemens)[0].feed, 254.0 / 60.0);  // G70: F unchanged
  ReaderOptions path;
  path.feedInMmPerSecond = true;
  EXPECT_DOUBLE_EQ(readProgram("G1 X1 F10\n", path)[0].feed, 10.0);
}

TEST(Gcode, ArcsByCentreAndByRadius) {
  // Quarter circle radius 10 from (10,0) to (0,10) about the origin, counter-clockwise, three ways.
  for (const char* program : {"G0 X10 Y0\nG3 X0 Y10 I-10 J0 F600\n", "G0 X10 Y0\nG3 X0 Y10 R10 F600\n",
                              "G0 X10 Y0\nG3 X0 Y10 CR=10 F600\n", "G0 X10 Y0\nG90.1 G3 X0 Y10 I0 J0 F600\n"}) {
    const Block arc = readProgram(program)[1];
    EXPECT_NEAR(arc.radius, 10.0, 1e-12) << program;
    EXPECT_NEAR(arc.sweep, M_PI / 2, 1e-12) << program;
    EXPECT_NEAR(arc.center.norm(), 0.0, 1e-9) << program;
    EXPECT_NEAR(arc.length(), 5 * M_PI, 1e-9);
    EXPECT_NEAR((arc.pointAt(arc.length() / 2) - Eigen::Vector3d(std::sqrt(50), std::sqrt(50), 0)).norm(), 0, 1e-9);
    EXPECT_NEAR((arc.tangent(false) - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-12);
  }
  // R < 0: the long way round (270°), clockwise.
  const Block longArc = readProgram("G0 X10 Y0\nG2 X0 Y10 R-10 F600\n")[1];
  EXPECT_NEAR(longArc.sweep, -1.5 * M_PI, 1e-12);
  // Full circle and a helix in G18 (ZX plane, normal Y).
  EXPECT_NEAR(readProgram("G0 X5\nG2 I-5 F100\n")[1].sweep, -2 * M_PI, 1e-12);
  const Block helix = readProgram("G18 G0 X10 Y0 Z0\nG3 X10 Y4 Z0 K0 I-10 F100\n")[1];
  EXPECT_EQ(helix.normal, Eigen::Vector3d::UnitY());
  EXPECT_NEAR(helix.length(), std::hypot(2 * M_PI * 10, 4.0), 1e-9);
}

TEST(Gcode, Siemens840dDialect) {
  const auto blocks = readProgram(
      "N10 G54 G17 G90 T=\"BALL4\" M6\nN20 CYCLE832(0.01,_ORI_FINISH,1)\nN30 G0 X0 Y0 Z5\nN40 G1 Z0 F2000\n"
      "N50 BRISK\nN60 G1 X10\nN70 G60 X20\nN80 G64 X30\nN90 G641 ADIS=0.05 X40\nN100 G4 F2.5\nN110 M30\n");
  ASSERT_EQ(blocks.size(), 6u);
  EXPECT_EQ(blocks[1].pathMode, PathMode::Rounding);  // CYCLE832: G642 within 0.01 mm, SOFT
  EXPECT_DOUBLE_EQ(blocks[1].tolerance, 0.01);
  EXPECT_EQ(blocks[1].jerkLimited, 1);
  EXPECT_EQ(blocks[2].jerkLimited, 0);
  EXPECT_EQ(blocks[3].pathMode, PathMode::ExactStop);
  EXPECT_EQ(blocks[4].pathMode, PathMode::Continuous);
  EXPECT_EQ(blocks[5].pathMode, PathMode::Rounding);
  EXPECT_DOUBLE_EQ(blocks[5].tolerance, 0.05);
  std::istringstream stream("G4 F2.5\nG4 P1\n");
  GcodeReader reader(stream);
  Block b;
  while (reader.next(b)) {
  }
  EXPECT_DOUBLE_EQ(reader.stats().dwellTime, 3.5);
}

TEST(Gcode, LinuxCncPathModes) {
  const auto blocks = readProgram("G61 G1 X1 F100\nG64 P0.02 X2\nG64 X3\nG9 X4\nX5\n");
  EXPECT_EQ(blocks[0].pathMode, PathMode::ExactStop);
  EXPECT_EQ(blocks[1].pathMode, PathMode::Rounding);
  EXPECT_DOUBLE_EQ(blocks[1].tolerance, 0.02);
  EXPECT_EQ(blocks[2].pathMode, PathMode::Continuous);
  EXPECT_EQ(blocks[3].pathMode, PathMode::ExactStop);  // G9: this block only
  EXPECT_EQ(blocks[4].pathMode, PathMode::Continuous);
}

// A word that would move the machine and is not understood stops the reading at its line (the time would be
// wrong without a word of it); skipped and counted only on request. Words that move nothing are counted.
TEST(Gcode, UnknownWordsStopTheReadingOrAreCounted) {
  EXPECT_EQ(errorOf("G1 X1 F100\nG1 X2 U5\n").rfind("line 2: 'U5' (an axis the simulator does not have) would move", 0), 0u)
      << errorOf("G1 X1 F100\nG1 X2 U5\n");
  EXPECT_EQ(errorOf("G0 X1\nG12.1 X3\n").rfind("line 2: 'G12.1' (a G code the simulator does not know)", 0), 0u);
  EXPECT_EQ(errorOf("G0 X1\nROT Z30\n").rfind("line 2: 'ROT' (a frame that turns", 0), 0u);
  EXPECT_NE(errorOf("G0 X1\nG16\n").find("--skip-unknown"), std::string::npos);  // says what to do
  ReaderOptions skipping;
  skipping.skipUnknownMotion = true;
  std::istringstream stream("G1 X1 F100 U5\nG28\nFOO\nG1 X2 E0.5\nROT Z10\nG1 X3\nM123\n");
  GcodeReader reader(stream, skipping);
  Block b;
  int moves = 0;
  while (reader.next(b)) ++moves;
  EXPECT_EQ(moves, 3);  // ROT Z10 turns a frame: when skipped, not a move either
  EXPECT_EQ(reader.stats().unknownWords, 4);  // U5 FOO ROT M123; G28 alone moves nothing
  EXPECT_EQ(reader.stats().unknownWordCounts.at("M123"), 1);
  EXPECT_EQ(reader.stats().unknownWordCounts.at("U5"), 1);
  ReaderOptions strict;
  strict.refuseUnknownWords = true;
  EXPECT_EQ(errorOf("G1 X1 F100\nG1 X2 M123\n", strict).rfind("line 2: 'M123' is not understood", 0), 0u);
}

TEST(Gcode, MalformedLinesNameTheirLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"G1 X1 F100\nG1 X1.2.3\n", "line 2: 'X1.2"},
      {"G1 X F100\n", "line 1: 'X "},
      {"G1 X1 F100\n(unclosed\n", "line 2: comment '(' is not closed"},
      {"X10\n", "line 1: coordinates before any motion mode"},
      {"G1 X10\n", "line 1: no feed rate"},
      {"G0 X10\nG2 X0 Y0 I-3 F100\n", "line 2: arc end point is not on the circle"},
      {"G0 X10\nG2 X-10 Y0 R3 F100\n", "line 2: arc radius 3.000000 mm is less than half the chord"},
      {"G0 X10\nG2 X0 Y10 F100\n", "line 2: arc without centre"},
      {"G1 X1 X2 F100\n", "line 1: axis X given twice"},
      {"G1 X1 F-5\n", "line 1: feed rate F-5"},
      {"G1 X1 F100 #5\n", "line 1: a parameter stands alone"},  // LinuxCNC's language: #5 = ... sets it
      {"G1 X1 F100 $5\n", "line 1: unexpected character '$'"},
      {"CYCLE832(0.01\n", "line 1: 'CYCLE832(' is not closed"},
  };
  for (const auto& [program, expected] : cases)
    EXPECT_EQ(errorOf(program).rfind(expected, 0), 0u) << program << " -> " << errorOf(program);
}

TEST(Gcode, LargeProgramsAreStreamed) {
  std::ostringstream text;
  text << "G1 F1000\n";
  for (int i = 0; i < 300000; ++i) text << "X" << (i % 2 ? 1.5 : 0.5) << " Y" << i * 0.001 << "\n";
  std::istringstream stream(text.str());
  GcodeReader reader(stream);
  Block b;
  long n = 0;
  while (reader.next(b)) ++n;
  EXPECT_EQ(n, 300000);
  EXPECT_EQ(reader.stats().lines, 300001);
}

TEST(Gcode, FuzzedProgramsNeverCrash) {
  const std::string seed =
      "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG2 X10 Y0 I5 J0\nG3 X0 Y0 R5\nCYCLE832(0.01,1)\nG64 P0.01\n"
      "G1 X-3.5 Y+2 (c) ; c\nSOFT\nG4 P1\nM30\n";
  const std::string alphabet = "GXYZIJKFRPMNT0123456789.-+ ()\n;=CYCLE832SOFT%/\t\r#abc";
  std::mt19937 random(11);
  int parsed = 0, refused = 0;
  for (int round = 0; round < 20000; ++round) {
    const std::string program = hsm::test::mutated(seed, alphabet, random);
    try {
      for (const Block& b : readProgram(program)) {
        ASSERT_TRUE(b.start.allFinite() && b.end.allFinite());
        ASSERT_TRUE(std::isfinite(b.length()));
      }
      ++parsed;
    } catch (const hsm::InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(parsed, 1000);
  EXPECT_GT(refused, 1000);
}

TEST(GcodeReader, NumbersReadExactlyAsTheGeneralParserReadsThem) {
  // The fast path (up to 15 digits) and fast_float (beyond) give the same, correctly rounded doubles.
  for (const char* text : {"12.3456", "0.05", "-0.0001", "+7", "5.", ".25", "-.5", "123456789.123456", "0.1",
                           "999999999", "0.000000000000000000000001", "123456789.12345678", "0.30000000000000004"}) {
    const auto blocks = readProgram(std::string("G0 X") + text + "\n");
    ASSERT_EQ(blocks.size(), std::strtod(text, nullptr) == 0.0 ? 0u : 1u) << text;
    if (!blocks.empty()) {
      EXPECT_EQ(blocks[0].end.x(), std::strtod(text, nullptr)) << text;
    }
  }
  for (const char* bad : {"1.2.3", "1e5", "--1", "1..2"})
    EXPECT_THROW(readProgram(std::string("G0 X") + bad + "\n"), ParseError) << bad;
}

TEST(GcodeLexer, RandomNumbersReadAsStrtodReadsThem) {
  // The fast path (up to 15 significant digits) and fast_float (beyond) on every length of integer and fraction
  // part, with leading zeros, signs and what may follow a number (a word, a blank, a comment, the line's end).
  std::mt19937 random(20261205);
  const char* after[] = {"", " Y1", "Y-2.5", ";note", "(c)", "\t", " "};
  for (int trial = 0; trial < 20000; ++trial) {
    std::string number = trial % 3 == 0 ? "-" : trial % 7 == 0 ? "+" : "";
    const int zeros = random() % 4, whole = random() % 10, fraction = random() % 20;
    number += std::string(zeros, '0');
    for (int i = 0; i < whole; ++i) number += char('0' + random() % 10);
    if (fraction > 0 || whole + zeros == 0) number += '.';
    for (int i = 0; i < std::max(fraction, whole + zeros == 0 ? 1 : 0); ++i) number += char('0' + random() % 10);
    const std::string line = "X" + number + after[trial % 7];
    detail::Line parsed;
    parsed.parse(line, 1);
    ASSERT_GE(parsed.wordCount, 1) << line;
    EXPECT_EQ(parsed.words[0].value, std::strtod(number.c_str(), nullptr)) << line;
    EXPECT_EQ(parsed.words[0].text, "X" + number) << line;
  }
}

namespace {
std::vector<double> endZ(const std::vector<Block>& blocks) {
  std::vector<double> z;
  for (const Block& b : blocks) z.push_back(b.end.z());
  return z;
}
}  // namespace

// LinuxCNC 2.9's G-code reference, "G81 Drilling Cycle" (preliminary motion, retract by G98/G99): across at the
// start Z, down to R, drill to Z, back to the start Z (G98); the next hole from there.
TEST(CannedCycles, G81DrillsEachHoleAndReturnsToTheStartZWithG98) {
  const auto blocks = readProgram("G0 X0 Y0 Z10\nG98 G81 X5 Y0 Z-3 R2 F60\nX10\nG80\nG0 X0\n");
  ASSERT_EQ(blocks.size(), 1u + 4u + 4u + 1u);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(5, 0, 10));
  EXPECT_EQ(blocks[1].motion, Motion::Rapid);
  EXPECT_EQ(endZ({blocks.begin() + 2, blocks.begin() + 5}), (std::vector<double>{2, -3, 10}));
  EXPECT_EQ(blocks[3].motion, Motion::Linear);
  EXPECT_DOUBLE_EQ(blocks[3].feed, 1.0);  // F60 mm/min
  EXPECT_EQ(blocks[4].motion, Motion::Rapid);
  EXPECT_EQ(blocks[5].end, Eigen::Vector3d(10, 0, 10));
  EXPECT_EQ(blocks[6].end.z(), 2.0);
  EXPECT_EQ(blocks[7].end.z(), -3.0);
  EXPECT_EQ(blocks[7].line, 3);  // the second hole is line 3's
  EXPECT_EQ(blocks[9].end, Eigen::Vector3d(0, 0, 10));  // after G80, G0 moves again
}

// G99 retracts to R between holes; a start below R first goes up to R (LinuxCNC's preliminary motion).
TEST(CannedCycles, G99RetractsToRAndAStartBelowRGoesUpFirst) {
  const auto blocks = readProgram("G0 X0 Y0 Z-1\nG99 G81 X5 Z-3 R2 F60\nX10\n");
  EXPECT_EQ(endZ(blocks), (std::vector<double>{-1, 2, 2, -3, 2, 2, -3, 2}));
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(0, 0, 2));
  EXPECT_EQ(blocks[2].end, Eigen::Vector3d(5, 0, 2));
}

// G83: pecks of Q, back to R after each, rapidly down to 0.254 mm above the last depth; G73 breaks the chip by
// 0.254 mm; G82 adds its dwell P per hole; G85 feeds back out.
TEST(CannedCycles, PecksDwellsAndFeedOut) {
  auto feeds = [](const std::vector<Block>& blocks) {
    std::vector<double> z;
    for (const Block& b : blocks)
      if (b.motion == Motion::Linear) z.push_back(b.end.z());
    return z;
  };
  const auto g83 = readProgram("G0 X0 Y0 Z5\nG98 G83 X0 Y0 Z-5 R1 Q2 F60\n");
  EXPECT_EQ(feeds(g83), (std::vector<double>{-1, -3, -5}));
  EXPECT_EQ(endZ(g83), (std::vector<double>{5, 1, -1, 1, -1 + 0.254, -3, 1, -3 + 0.254, -5, 5}));
  const auto g73 = readProgram("G0 X0 Y0 Z5\nG99 G73 X0 Y0 Z-5 R1 Q2 F60\n");
  EXPECT_EQ(endZ(g73), (std::vector<double>{5, 1, -1, -1 + 0.254, -3, -3 + 0.254, -5, 1}));
  std::istringstream program("G0 X0 Y0 Z5\nG98 G82 X0 Y0 Z-2 R1 P0.5 F60\nX5\nG85 X10 Z-2 R1\n");
  GcodeReader reader(program);
  Block block;
  std::vector<Block> blocks;
  while (reader.next(block)) blocks.push_back(block);
  EXPECT_DOUBLE_EQ(reader.stats().dwellTime, 1.0);  // two holes of G82 P0.5
  EXPECT_EQ(blocks.back().motion, Motion::Rapid);
  EXPECT_EQ(blocks[blocks.size() - 2].motion, Motion::Linear);  // G85 feeds back out to R
  EXPECT_EQ(blocks[blocks.size() - 2].end, Eigen::Vector3d(10, 0, 1));
  EXPECT_EQ(reader.stats().unknownWords, 0);
}

TEST(CannedCycles, WhatCannotBeReadIsNamed) {
  EXPECT_EQ(errorOf("G0 Z5\nG81 X1 Z-2 F60\n").rfind("line 2: G81 needs R", 0), 0u) << errorOf("G0 Z5\nG81 X1 Z-2 F60\n");
  EXPECT_EQ(errorOf("G0 Z5\nG83 X1 Z-2 R1 F60\n").rfind("line 2: G83 needs Q > 0", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z5\nG81 X1 Z3 R1 F60\n").rfind("line 2: G81: the bottom Z3 is above the retract plane R1", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z5\nG18 G81 X1 Z-2 R1 F60\n").rfind("line 2: G81 in G18", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z5\nG81 X1 Z-2 R1\n").rfind("line 2: G81 drills at F0", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z5\nG83 X1 Z-1000000 R1 Q0.001 F60\n").rfind("line 2: G83: ", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z5\nG82 X1 Z-2 R1 P-5 F60\n").rfind("line 2: G82 P-5: a dwell lasts 0 s or more", 0), 0u);
}

// LinuxCNC 2.9's G-code reference, "G33.1 Rigid Tapping": in to Z synchronised with the spindle (the feed is
// S times the pitch K), then out to where it started with the spindle reversed.
TEST(CannedCycles, RigidTappingGoesInAtTheSpindlesPitchAndBackOut) {
  const auto blocks = readProgram("G21 G90 S200 M3\nG0 X0 Y0 Z10\nG33.1 Z-5 K1.25\nG0 X5\n");
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(0, 0, -5));
  EXPECT_EQ(blocks[1].motion, Motion::Linear);
  EXPECT_DOUBLE_EQ(blocks[1].feed, 200 * 1.25 / 60.0);  // 250 mm/min
  EXPECT_EQ(blocks[2].end, Eigen::Vector3d(0, 0, 10));
  EXPECT_EQ(blocks[3].start, Eigen::Vector3d(0, 0, 10));
  EXPECT_NE(errorOf("G0 Z10\nG33.1 Z-5 K1\n").find("line 2: G33.1 taps at S0"), std::string::npos);
  EXPECT_NE(errorOf("S100 G0 Z10\nG33.1 Z-5\n").find("line 2: G33.1 needs K > 0"), std::string::npos);
}

// SINUMERIK 840D sl Cycles Programming Manual, "Drilling cycles" (CYCLE81 … CYCLE89) and "Modal call (MCALL)":
// at the current X Y, rapid to RFP + SDIS, in to DP (or DPR below RFP), back to RTP; MCALL calls the cycle
// after every move from the next one on, until MCALL alone.
TEST(SiemensCycles, DrillingCyclesAndTheirModalCall) {
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  const auto once = readProgram("G0 X10 Y5 Z50\nG1 F100\nCYCLE81(20, 0, 2, -10)\nG0 X0\n", siemens);
  ASSERT_EQ(once.size(), 5u);
  EXPECT_EQ(once[1].end, Eigen::Vector3d(10, 5, 2));
  EXPECT_EQ(once[1].motion, Motion::Rapid);
  EXPECT_EQ(once[2].end, Eigen::Vector3d(10, 5, -10));
  EXPECT_EQ(once[2].motion, Motion::Linear);
  EXPECT_EQ(once[2].pathMode, PathMode::ExactStop);
  EXPECT_EQ(once[3].end, Eigen::Vector3d(10, 5, 20));
  EXPECT_EQ(once[4].pathMode, PathMode::Continuous);  // the path mode comes back after the cycle
  std::istringstream modal("G0 X0 Y0 Z20\nG1 F100\nMCALL CYCLE82(10, 0, 1, , 5, 0.5)\nG0 X10\nX20\nMCALL\nX30\n");
  GcodeReader reader(modal, siemens);
  std::vector<Block> blocks;
  for (Block b; reader.next(b);) blocks.push_back(b);
  std::vector<double> bottoms;
  for (const Block& b : blocks)
    if (b.motion == Motion::Linear) bottoms.push_back(b.end.x());
  EXPECT_EQ(bottoms, (std::vector<double>{10, 20}));  // DPR 5: 5 mm below RFP 0
  EXPECT_DOUBLE_EQ(reader.stats().dwellTime, 1.0);
  EXPECT_EQ(blocks.back().end, Eigen::Vector3d(30, 0, 10));  // after MCALL alone: no cycle
  // CYCLE83, swarf removal (VARI 1): pecks of FDPR 4 to DP -10 from RFP 0, back to RFP + SDIS after each
  const auto deep = readProgram("G0 X0 Y0 Z20\nG1 F100\nCYCLE83(10, 0, 1, -10, , , 4, 0, 0, 0, 1, 1)\n", siemens);
  int pecks = 0;
  for (const Block& b : deep) pecks += b.motion == Motion::Linear;
  EXPECT_EQ(pecks, 3);  // 1 -> -3 -> -7 -> -10
  // CYCLE83 with the degression DAM 1: pecks of 4, 3, 2, then 1 (DAM the least)
  const auto degressive = readProgram("G0 X0 Y0 Z20\nG1 F100\nCYCLE83(10, 0, 1, -10, , , 4, 1, 0, 0, 1, 1)\n", siemens);
  std::vector<double> bottoms83;
  for (const Block& b : degressive)
    if (b.motion == Motion::Linear) bottoms83.push_back(b.end.z());
  EXPECT_EQ(bottoms83, (std::vector<double>{-3, -6, -8, -9, -10}));
  // R parameters and variables as arguments: their values (Job Planning 1.3: arguments are expressions)
  const auto computed = readProgram("R1=10 R2=-5\nG0 X0 Y0 Z20\nG1 F100\nCYCLE81(R1, 0, 1, R2*2)\n", siemens);
  EXPECT_DOUBLE_EQ(computed[computed.size() - 2].end.z(), -10.0);
  EXPECT_DOUBLE_EQ(computed.back().end.z(), 10.0);
  EXPECT_EQ(errorOf("G0 Z20\nG1 F100\nCYCLE81(_NOPE, 0, 1, -5)\n", siemens)
                .rfind("line 3: CYCLE81 argument 1 '_NOPE' is neither a number nor an R parameter", 0), 0u);
  EXPECT_EQ(errorOf("G0 Z20\nG1 F100\nCYCLE81(10, 0)\n", siemens).rfind("line 3: CYCLE81 needs RTP, RFP and DP", 0), 0u);
  EXPECT_EQ(readProgram("G505 G0 X1\nG503 X2\nG500 X3\n", siemens).size(), 3u);  // settable zero offsets
}

// SINUMERIK 840D sl Programming Manual Fundamentals, "Frames": TRANS replaces the programmable frame by a
// translation, ATRANS adds one, TRANS (or ROT) alone clears it; a rotation stops the reading.
TEST(SiemensFrames, TranslationsShiftTheProgram) {
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  const auto blocks = readProgram("G0 X1 Y1 Z10\nTRANS X10 Y5\nG0 X0 Y0\nATRANS X1\nG0 X0\nTRANS\nG0 X0 Y0\nROT\n", siemens);
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(10, 5, 10));
  EXPECT_EQ(blocks[2].end, Eigen::Vector3d(11, 5, 10));
  EXPECT_EQ(blocks[3].end, Eigen::Vector3d(0, 0, 10));
  EXPECT_EQ(errorOf("G0 X0\nTRANS X1 A5\n", siemens).rfind("line 2: TRANS with 'A5': a frame instruction stands in a block of its own", 0), 0u);
  EXPECT_EQ(readProgram("CYCLE800()\nG0 X1\n", siemens).size(), 1u);  // a swivel deselected: nothing moves
}

// SINUMERIK 840D sl Job Planning, "Flexible NC programming": R parameters, DEF variables, arithmetic and the
// standard functions, assignments to addresses (X=R1+5, CR=…); SUPA moves in machine coordinates.
TEST(SiemensVariables, ParametersVariablesAndAssignments) {
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  siemens.conventions.workOffset = Eigen::Vector3d(0, 0, -300);
  const auto blocks = readProgram(
      "DEF REAL _DEPTH=-2, _STEP\nR1=10 R2=R1*2+SQRT(16)\n_STEP=R2 DIV 5\nG1 F100 X=R1+5 Y=_STEP Z=_DEPTH\n"
      "G2 X=R1 Y=R2-24 CR=POT(3)-4\nR3=ATAN2(1,1)+MINVAL(2,3)+TRUNC(-1.5)+7 MOD 4\nG1 X=R3 ; R4=99\n"
      "SUPA G0 Z0\n",
      siemens);
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[0].end, Eigen::Vector3d(15, 4, -2));  // R2 = 24, _STEP = 24 DIV 5 = 4
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(10, 0, -2));
  EXPECT_DOUBLE_EQ(blocks[1].radius, 5.0);
  EXPECT_DOUBLE_EQ(blocks[2].end.x(), 45.0 + 2.0 - 1.0 + 3.0);
  EXPECT_DOUBLE_EQ(blocks[3].end.z(), 300.0);  // machine Z0, 300 mm above the program's zero
  EXPECT_EQ(errorOf("G1 X=R1+_NOPE F100\n", siemens).rfind("line 1: '_NOPE' is neither an R parameter nor a variable", 0), 0u);
  EXPECT_EQ(errorOf("R1=1/0\n", siemens).rfind("line 1: division by zero", 0), 0u);
  EXPECT_EQ(errorOf("R1=SQRT(-1)\n", siemens).rfind("line 1: SQRT(-1)", 0), 0u);
  EXPECT_EQ(errorOf("DEF LONG X1\n", siemens).rfind("line 1: DEF LONG: the types read are REAL", 0), 0u);
  EXPECT_EQ(errorOf("R1=1E9\n", siemens).rfind("line 1: a number with an exponent", 0), 0u);
  EXPECT_EQ(errorOf("R9999=1\n", siemens).rfind("line 1: R9999 is not an R parameter: they are R0 to R999", 0), 0u);
  // X=IC(…) / X=AC(…): that axis incremental / absolute on this block, whatever G90 / G91 say
  const auto perAxis = readProgram("G90 G1 X10 F100\nX=IC(5) Y=AC(3)\nG91\nX=AC(1) Z=IC(R1+2) A=AC(30)\n", siemens);
  ASSERT_EQ(perAxis.size(), 3u);
  EXPECT_EQ(perAxis[1].end, Eigen::Vector3d(15, 3, 0));
  EXPECT_EQ(perAxis[2].end, Eigen::Vector3d(1, 3, 2));
  EXPECT_DOUBLE_EQ(perAxis[2].rotaryEnd.x(), 30.0);
  EXPECT_EQ(errorOf("R1=IC(5)\n", siemens).rfind("line 1: IC() gives one axis an incremental value", 0), 0u);
}

// Mutations of a program in the 840D's variables, cycles and frames are read or refused with an InputError.
TEST(SiemensVariables, FuzzedProgramsAreReadOrRefusedNeverCrash) {
  const std::string seed =
      "DEF REAL _D=-2, _S\nR1=10 R2=R1*2+SQRT(16)\n_S=R2 DIV 5\nG1 F100 X=R1+5 Y=_S Z=_D\nG2 X=R1 Y=R2-24 CR=POT(3)-4\n"
      "TRANS X5\nATRANS Y=R1\nMCALL CYCLE83(10, 0, 1, -10, , , 4, 0, 0, 0, 1, 1)\nG0 X20\nMCALL\nTRANS\n"
      "SUPA G0 Z0\nCYCLE81(20, 0, 2, -10)\nT=\"DRILL 8.5\" M6\nR3=ATAN2(1,1)+MINVAL(2,3)+7 MOD 4\nG1 X=R3\n";
  const std::string alphabet = "RDEF_=()+-*/,. \n0123456789XYZGCTRANSMOPQIVL\"";
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  ASSERT_GT(readProgram(seed, siemens).size(), 10u);
  hsm::test::expectReadAndRefused(seed, alphabet, siemens, 13);
}
