// The 840D's program flow, each construct's expected moves worked out from SINUMERIK 840D sl Programming Manual
// Job Planning (6FC5398-2BP40), chapter 1 "Flexible NC programming": 1.10 "Program jumps and branches" (labels,
// GOTOF / GOTOB / GOTO / GOTOC, IF ... GOTO), 1.11 "Program section repetition" (REPEAT, REPEATB), 1.12 "Control
// structures" (IF-ELSE-ENDIF, LOOP, FOR, WHILE, REPEAT-UNTIL), and chapter 2 "Subprogram technique" (L123, calls
// by name with PROC parameters, P passes, CALL, RET / M17, local variables).
#include "kinematics/gcode.hpp"

#include "support/gcode_errors.hpp"
#include "support/reader_fuzz.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace hsm::kinematics;
using hsm::test::errorOf;

namespace {
ReaderOptions siemens() {
  ReaderOptions options;
  options.conventions.dialect = Dialect::Siemens840D;
  return options;
}

std::vector<Eigen::Vector3d> ends(const std::vector<Block>& blocks) {
  std::vector<Eigen::Vector3d> out;
  for (const Block& b : blocks) out.push_back(b.end);
  return out;
}

using Points = std::vector<Eigen::Vector3d>;

// A folder of subprogram files, removed with the test.
struct SubprogramFolder {
  explicit SubprogramFolder(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~SubprogramFolder() { std::filesystem::remove_all(path); }
  void write(const std::string& file, const std::string& text) const { std::ofstream(path / file) << text; }
  std::filesystem::path path;
};
}  // namespace

// 1.10: a jump label ends with ':' at the block's start (after its N number); GOTOF searches forward, GOTOB
// backward, GOTO forward then backward, GOTOC the same without an alarm when the label is missing; a block number
// is a destination too. The same label may stand several times: each search takes the nearest in its direction.
TEST(SiemensLanguage, LabelsAndJumps) {
  const auto blocks = readProgram(
      "R1=0\n"
      "LOOP1: R1=R1+1\n"
      "G1 F1000 X=R1*10\n"
      "IF R1<3 GOTOB LOOP1\n"
      "GOTOF SKIP\n"
      "G1 X999\n"
      "N40 SKIP: G1 Y5\n"
      "GOTOF N50\n"
      "G1 X888\n"
      "N50 G1 Y6\n"
      "GOTOC NOWHERE\n"
      "G1 Y7\n"
      "R6=9\n"
      "START: G1 Z=R6\n"
      "R6=R6-3\n"
      "IF R6>=0 GOTOB START\n"
      "R6=2\n"
      "START: G1 X=R6\n"
      "R6=R6-1\n"
      "IF R6>0 GOTOB START\n",
      siemens());
  EXPECT_EQ(ends(blocks), (Points{{10, 0, 0}, {20, 0, 0}, {30, 0, 0}, {30, 5, 0}, {30, 6, 0}, {30, 7, 0},
                                  {30, 7, 9}, {30, 7, 6}, {30, 7, 3}, {30, 7, 0}, {2, 7, 0}, {1, 7, 0}}));
  // Lines stream through until one a jump may come back to (a block number, a label, a statement): the jump
  // back to the block number, or to the first label, finds its line
  const auto numbered = readProgram("G1 F100 X1\nG1 X2\nN30 G1 X3\nG1 X4\nR2=R2+1\nIF R2<2 GOTOB N30\n", siemens());
  EXPECT_EQ(ends(numbered), (Points{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {3, 0, 0}, {4, 0, 0}}));
  const auto late = readProgram("R1=0\nG1 F100 X1\nAGAIN: R1=R1+1\nG1 Y=R1\nIF R1<2 GOTOB AGAIN\nM30\nG1 X9\n", siemens());
  EXPECT_EQ(ends(late), (Points{{1, 0, 0}, {1, 1, 0}, {1, 2, 0}}));
  EXPECT_EQ(errorOf("G1 F100 X1\nGOTOF NOPE\nNOPE_NOT: X2\n", siemens()).rfind("line 2: label NOPE is not after this line", 0), 0u);
  EXPECT_EQ(errorOf("BACK: G1 F100 X1\nGOTOB ELSEWHERE\n", siemens()).rfind("line 2: label ELSEWHERE is not before", 0), 0u);
  EXPECT_EQ(errorOf("GOTOF\n", siemens()).rfind("line 1: GOTOF needs the label", 0), 0u);
  EXPECT_EQ(errorOf("IF R1== GOTOF X\n", siemens()).rfind("line 1: ", 0), 0u);
}

// 1.12: IF-ELSE-ENDIF (nested), conditions with comparisons and AND / OR / NOT, FOR counts up by 1 to its end
// value (a start beyond it runs nothing), WHILE tests before each pass, REPEAT-UNTIL after, LOOP turns until a
// jump leaves it.
TEST(SiemensLanguage, ControlStructures) {
  const auto blocks = readProgram(
      "DEF INT I\n"
      "R1=5\n"
      "IF R1>3\n"
      "  G1 F100 X1\n"
      "ELSE\n"
      "  G1 X2\n"
      "ENDIF\n"
      "IF R1==0 AND NOT (R1<>5)\n"
      "  G1 X3\n"
      "ELSE\n"
      "  IF R1>=5 OR R1<0\n"
      "    G1 X4\n"
      "  ENDIF\n"
      "ENDIF\n"
      "FOR I=1 TO 3\n"
      "  G1 Y=I\n"
      "ENDFOR\n"
      "FOR I=5 TO 1\n"
      "  G1 X99\n"
      "ENDFOR\n"
      "R2=0\n"
      "WHILE R2<2\n"
      "  R2=R2+1\n"
      "  G1 Z=R2\n"
      "ENDWHILE\n"
      "REPEAT\n"
      "  R2=R2-1\n"
      "  G1 Z=R2\n"
      "UNTIL R2<=0\n"
      "LOOP\n"
      "  R2=R2+10\n"
      "  IF R2>20 GOTOF OUT\n"
      "  G1 X=R2\n"
      "ENDLOOP\n"
      "OUT: G1 X0\n",
      siemens());
  EXPECT_EQ(ends(blocks), (Points{{1, 0, 0}, {4, 0, 0}, {4, 1, 0}, {4, 2, 0}, {4, 3, 0}, {4, 3, 1}, {4, 3, 2},
                                  {4, 3, 1}, {4, 3, 0}, {10, 3, 0}, {20, 3, 0}, {0, 3, 0}}));
  EXPECT_EQ(errorOf("R1=1\nIF R1>3\nG1 F100 X1\n", siemens()).rfind("line 2: IF has no ENDIF", 0), 0u);
  EXPECT_EQ(errorOf("ENDWHILE\n", siemens()).rfind("line 1: ENDWHILE without its opening statement", 0), 0u);
  EXPECT_EQ(errorOf("FOR _K=1 TO 3\nENDFOR\n", siemens()).rfind("line 1: FOR _K: the counter is an R parameter", 0), 0u);
  EXPECT_EQ(errorOf("IF R1>3 G1 X5\n", siemens()).rfind("line 1: IF <condition> is followed by GOTOF", 0), 0u);
}

// 1.11: REPEAT <label> P=n runs the section from the label to the REPEAT block n times more; REPEAT <label>
// <label> the section between the two labels; REPEATB <label> the labelled block alone. Then the program goes
// on after the REPEAT block.
TEST(SiemensLanguage, SectionRepetition) {
  const auto blocks = readProgram(
      "G1 F100 X1\n"
      "ROW: G91 Y1\n"
      "G90\n"
      "REPEAT ROW P=2\n"
      "FIRST_Z: G91 Z1\n"
      "LAST_Z: Z1\n"
      "G90 X5\n"
      "REPEAT FIRST_Z LAST_Z\n"
      "G90 G1 X7\n"
      "REPEATB ROW P=3\n"
      "G90 X8\n",
      siemens());
  EXPECT_EQ(ends(blocks), (Points{{1, 0, 0}, {1, 1, 0}, {1, 2, 0}, {1, 3, 0}, {1, 3, 1}, {1, 3, 2}, {5, 3, 2},
                                  {5, 3, 3}, {5, 3, 4}, {7, 3, 4}, {7, 4, 4}, {7, 5, 4}, {7, 6, 4}, {8, 6, 4}}));
  EXPECT_EQ(errorOf("REPEAT NOWHERE P=2\n", siemens()).rfind("line 1: label NOWHERE is not before", 0), 0u);
  EXPECT_EQ(errorOf("ROW: G1 F100 X1\nREPEAT ROW P=-1\n", siemens()).rfind("line 2: REPEAT P=-1: the passes", 0), 0u);
}

// Chapter 2: a subprogram is a file NAME.SPF (or L123.SPF) beside the program or in a folder given; called by
// its name alone, with arguments for its PROC's parameters, with P passes, or by CALL "NAME"; RET or M17 return
// (M30 ends the main program). Its DEF variables are its own (the caller's are not seen); R parameters are the
// control's. A missing subprogram stops the program (alarm 14011): refused, named.
TEST(SiemensLanguage, SubprogramsFromFiles) {
  const SubprogramFolder folder("hsm_siemens_subs");
  folder.write("L10.SPF", "%_N_L10_SPF\n;$PATH=/_N_SPF_DIR\nG91 G1 X1\nG90\nM17\n");
  folder.write("POCKET_ROW.SPF", "PROC POCKET_ROW(REAL DEPTH, VAR INT COUNT) SAVE DISPLOF\nDEF INT K\n"
                                 "FOR K=1 TO COUNT\n  G1 Z=DEPTH*K\nENDFOR\nR10=R10+1\nRET\n");
  folder.write("SEES_CALLER.SPF", "G1 X=_MINE\nRET\n");
  folder.write("DEEP.SPF", "DEEP\nRET\n");
  folder.write("BAD_ARC.SPF", "G1 F100 X1\nG2\nRET\n");
  ReaderOptions options = siemens();
  options.subroutineFolders = {folder.path.string()};
  const auto blocks = readProgram(
      "DEF REAL _MINE=3\nR10=0\nG0 X0 Y0 Z5\nG1 F100 Y1\nL10 P3\nPOCKET_ROW(-1, 2)\nCALL \"L10\"\nG1 Y=R10+5\n"
      "M30\nG1 X99\n",
      options);
  EXPECT_EQ(ends(blocks), (Points{{0, 0, 5}, {0, 1, 5}, {1, 1, 5}, {2, 1, 5}, {3, 1, 5}, {3, 1, -1}, {3, 1, -2},
                                  {4, 1, -2}, {4, 6, -2}}));
  EXPECT_EQ(errorOf("MISSING_ONE\n", options).rfind("line 1: subprogram MISSING_ONE is not found (looked for MISSING_ONE.SPF", 0), 0u);
  EXPECT_NE(errorOf("TRAOOF\n", options).find("or is it a misspelt TRAFOOF?"), std::string::npos);
  EXPECT_EQ(errorOf("POCKET_ROW(1, 2, 3)\n", options).rfind("line 1: POCKET_ROW takes 2 parameters", 0), 0u);
  const std::string hidden = errorOf("DEF REAL _MINE=3\nG1 F100 X1\nSEES_CALLER\n", options);
  EXPECT_EQ(hidden.rfind("line 1: '_MINE' is neither an R parameter nor a variable", 0), 0u) << hidden;
  EXPECT_NE(hidden.find("(in SEES_CALLER.SPF)"), std::string::npos) << hidden;
  EXPECT_NE(errorOf("DEEP\n", options).find("nested more than 16 levels deep"), std::string::npos);
  EXPECT_EQ(errorOf("BAD_ARC\n", options).rfind("line 2: G2 without an end point or a centre", 0), 0u);
  EXPECT_NE(errorOf("BAD_ARC\n", options).find("(in BAD_ARC.SPF)"), std::string::npos);
  EXPECT_EQ(errorOf("L10 X5\n", options).rfind("line 1: the call of L10 shares its block with 'X5'", 0), 0u);
  EXPECT_EQ(errorOf("PROC MAIN_AS_SUB(REAL A)\nG1 F100 X=A\n", options).rfind("line 1: this is subprogram MAIN_AS_SUB", 0), 0u);

  // Skipping unknown motion: the missing call is counted and named, the rest is read.
  options.skipUnknownMotion = true;
  std::istringstream text("MISSING_ONE\nG1 F100 X1\n");
  GcodeReader reader(text, options);
  Block block;
  int count = 0;
  while (reader.next(block)) ++count;
  EXPECT_EQ(count, 1);
  EXPECT_EQ(reader.stats().unknownWordCounts.count("MISSING_ONE"), 1u);
}

// Loops, jumps back and repeats are bounded: an endless one is refused, naming it, instead of running on.
TEST(SiemensLanguage, EndlessLoopsAreRefused) {
  ReaderOptions options = siemens();
  options.maxLoopIterations = 1000;
  EXPECT_EQ(errorOf("G1 F100 X0\nLOOP\nG91 X1\nENDLOOP\n", options).rfind("line 4: LOOP ... ENDLOOP (left only by a jump) has turned 1000 times", 0), 0u);
  EXPECT_EQ(errorOf("AGAIN: G1 F100 X1\nGOTOB AGAIN\n", options).rfind("line 2: the program has jumped back to the same line 1000 times", 0), 0u);
  EXPECT_EQ(errorOf("R1=0\nWHILE R1<1\nG91 G1 F100 X1\nENDWHILE\n", options).rfind("line 4: WHILE ... ENDWHILE has turned 1000 times", 0), 0u);
  EXPECT_EQ(errorOf("ROW: G1 F100 X1\nREPEAT ROW P=5000\n", options).rfind("line 2: REPEAT P=5000: the passes are a whole number from 0 to 1000", 0), 0u);
}

// Mutations of a program in the 840D's flow statements are read or refused with an InputError, never a crash or
// an endless run.
TEST(SiemensLanguage, FuzzedFlowIsReadOrRefused) {
  const std::string seed =
      "DEF INT I\nR1=0\nMARK: R1=R1+1\nG1 F100 X=R1\nIF R1<3 GOTOB MARK\nIF R1==3\nG1 Y1\nELSE\nG1 Y2\nENDIF\n"
      "FOR I=1 TO 2\nG1 Z=I\nENDFOR\nWHILE R1>0\nR1=R1-1\nENDWHILE\nREPEAT\nR1=R1+1\nUNTIL R1>2\n"
      "ROW: G91 X1\nG90\nREPEAT ROW P=2\nLOOP\nGOTOF OUT\nENDLOOP\nOUT: G1 X0\n";
  ReaderOptions options = siemens();
  options.maxLoopIterations = 1000;
  ASSERT_GT(readProgram(seed, options).size(), 8u);
  hsm::test::expectReadAndRefused(seed, "RIFGOTBMAKLSEWHNDUPX=<>+-:0123456789 \n", options, 47);
}

// Programming Manual Fundamentals, "Coordinate transformations (frames)": TRANS / ROT / SCALE / MIRROR replace the
// programmable frame, ATRANS / AROT / ASCALE / AMIRROR add to it in the coordinates it has made; ROT RPL= turns in
// the working plane; increments (G91) and arcs are in the frame's coordinates; ROT alone clears it.
TEST(SiemensFrames, TurnsScalesAndMirrors) {
  const auto blocks = readProgram(
      "G17 G0 X0 Y0 Z10\n"
      "TRANS X10 Y5\n"
      "ROT Z90\n"              // replaces the translation
      "G1 F100 X10 Y0\n"       // (10, 0) turned 90 degrees: (0, 10)
      "TRANS X10 Y5\n"
      "AROT RPL=90\n"
      "G1 X10 Y0\n"            // (10, 5) + (0, 10)
      "ATRANS X1\n"            // along the turned X: the world's Y
      "G1 X0 Y0\n"             // (10, 6)
      "G91 G1 X1\n"            // one more along the turned X: (10, 7)
      "G90\n"
      "SCALE X2 Y2\n"
      "G1 X5 Y5\n"             // (10, 10)
      "G2 X10 Y0 I0 J-5\n"     // centre (5, 0) scaled: (10, 0), radius 10, to (20, 0)
      "MIRROR X0\n"
      "G1 X5 Y5\n"             // (-5, 5)
      "ROT Y-90\n"             // about Y: the program's X goes down the world's Z, its Z along -X
      "G1 X100 Y0 Z20\n"       // (-20, 0, 100)
      "ROT\n"
      "G1 X0 Y0 Z0\n",
      siemens());
  const Points expected{{0, 0, 10},  {0, 10, 10}, {10, 15, 10}, {10, 6, 10},   {10, 7, 10},
                        {10, 10, 10}, {20, 0, 10}, {-5, 5, 10},  {-20, 0, 100}, {0, 0, 0}};
  ASSERT_EQ(blocks.size(), expected.size());
  for (size_t i = 0; i < blocks.size(); ++i)
    EXPECT_LT((blocks[i].end - expected[i]).norm(), 1e-9) << i << ": " << blocks[i].end.transpose();
  const Block& arc = blocks[6];
  EXPECT_TRUE(arc.center.isApprox(Eigen::Vector3d(10, 0, 10), 1e-9)) << arc.center.transpose();
  EXPECT_NEAR(arc.radius, 10.0, 1e-9);
  EXPECT_NEAR(arc.length(), 0.5 * M_PI * 10.0, 1e-9);
  EXPECT_TRUE(arc.pointAt(arc.length() / 2).isApprox(Eigen::Vector3d(10 + 10 * M_SQRT1_2, 10 * M_SQRT1_2, 10), 1e-9));
  // Under MIRROR X a G3 turns clockwise: from (5, 5) about (5, 0) to (10, 0) counter-clockwise is three quarters
  // through (0, 0) and (5, -5); mirrored, from (-5, 5) through (0, 0) and (-5, -5) to (-10, 0)
  const auto mirrored = readProgram("G0 X5 Y5\nMIRROR X0\nG1 F100 X5 Y5\nG3 X10 Y0 I0 J-5\n", siemens());
  ASSERT_EQ(mirrored.size(), 3u);
  EXPECT_TRUE(mirrored[2].end.isApprox(Eigen::Vector3d(-10, 0, 0), 1e-9));
  EXPECT_NEAR(mirrored[2].length(), 1.5 * M_PI * 5.0, 1e-9);
  EXPECT_TRUE(mirrored[2].pointAt(mirrored[2].length() / 3).isZero(1e-9)) << mirrored[2].pointAt(mirrored[2].length() / 3).transpose();
  EXPECT_TRUE(mirrored[2].pointAt(mirrored[2].length() * 2 / 3).isApprox(Eigen::Vector3d(-5, -5, 0), 1e-9));
  EXPECT_EQ(errorOf("SCALE X2\nG0 X5 Y5\nG2 X10 Y0 I0 J-5 F100\n", siemens()).rfind("line 3: an arc under a SCALE that differs", 0), 0u);
  EXPECT_EQ(errorOf("SCALE X0\n", siemens()).rfind("line 1: the frame would flatten the coordinates", 0), 0u);
  EXPECT_EQ(errorOf("ROT RPL=10 Z5\n", siemens()).rfind("line 1: ROT: RPL= turns in the plane", 0), 0u);
}

// Cycles Programming Manual, "Swiveling - CYCLE800": axis by axis (_MODE 57: X, then Y, then Z), the rotary axes
// turn the tool along the new plane's Z first (a block of its own, the linear axes standing), then the program's
// points are the tool tip in the swivelled plane; X0 Y0 Z0 shift before the turn, X1 Y1 Z1 after; _ST 1 adds to
// the plane in force; CYCLE800() takes the plane back.
TEST(SiemensFrames, Cycle800SwivelsTheToolAndThePlane) {
  const auto blocks = readProgram(
      "G17 G90 G0 X10 Y0 Z50\n"
      "CYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,1)\n"
      "G0 X0 Y0 Z20\n"
      "G1 F1000 X10\n"
      "CYCLE800()\n"
      "G0 X0\n"
      "CYCLE800(0,\"TC1\",0,57,100,0,0,0,0,90,5,0,0,1)\n"  // about Z alone: a frame, no swivel
      "G0 X0 Y0 Z10\n"
      "CYCLE800(0,\"TC1\",1,57,0,0,0,-30,0,0,0,0,0,1)\n"   // added: then about X by -30
      "G0 X0 Y0 Z10\n",
      siemens());
  ASSERT_EQ(blocks.size(), 8u);
  const double c = std::cos(M_PI / 6), s = 0.5;
  const Block& swivel = blocks[1];
  EXPECT_TRUE(swivel.start.isApprox(Eigen::Vector3d(10, 0, 50)) && swivel.end.isApprox(swivel.start));
  EXPECT_TRUE(swivel.orientationVectors && !swivel.toolTip && swivel.motion == Motion::Rapid);
  EXPECT_TRUE(swivel.orientationEnd.isApprox(Eigen::Vector3d(s, 0, c), 1e-12));
  EXPECT_TRUE(blocks[2].end.isApprox(Eigen::Vector3d(20 * s, 0, 20 * c), 1e-12));
  EXPECT_TRUE(blocks[3].end.isApprox(Eigen::Vector3d(10 * c + 20 * s, 0, -10 * s + 20 * c), 1e-12));
  for (int i : {2, 3}) EXPECT_TRUE(blocks[i].toolTip && blocks[i].orientationEnd.isApprox(Eigen::Vector3d(s, 0, c)));
  EXPECT_TRUE(blocks[4].end.isApprox(Eigen::Vector3d(0, 0, -10 * s + 20 * c), 1e-12));
  EXPECT_FALSE(blocks[4].toolTip || blocks[4].orientationVectors);
  EXPECT_TRUE(blocks[5].end.isApprox(Eigen::Vector3d(100, 5, 10), 1e-12)) << blocks[5].end.transpose();
  EXPECT_FALSE(blocks[5].orientationVectors);
  // Rz(90), then Rx(-30) about the turned X (the world's Y): the tool axis tips towards the world's -X
  EXPECT_TRUE(blocks[6].orientationEnd.isApprox(Eigen::Vector3d(-s, 0, c), 1e-12)) << blocks[6].orientationEnd.transpose();
  EXPECT_TRUE(blocks[7].end.isApprox(Eigen::Vector3d(100 - 10 * s, 5, 10 * c), 1e-12)) << blocks[7].end.transpose();
  EXPECT_EQ(errorOf("CYCLE800(1,\"TC1\",0,192,0,0,0,0,30,0,0,0,0,1)\n", siemens())
                .rfind("line 1: 'CYCLE800' (a swivel in solid angles", 0), 0u);
  EXPECT_EQ(errorOf("CYCLE800(1,\"TC1\",0,300,0,0,0,0,30,0,0,0,0,1)\n", siemens())
                .rfind("line 1: CYCLE800 _MODE 300 is not a swivel mode", 0), 0u);
}

// Fundamentals, "Circular interpolation with intermediate and end points (CIP)": the arc through three points in
// whatever plane they span; in a turned frame the arc turns with it. A measuring cycle (CYCLE9xx) moves nothing
// the simulator can time: counted and named, the rest read.
TEST(SiemensLanguage, ArcsThroughAPointAndMeasuringCycles) {
  const auto blocks = readProgram("G0 X10 Y0 Z0\nG1 F100 X10\nCIP X-10 Y0 Z0 I1=0 J1=7.0710678118654755 K1=7.0710678118654755\n"
                                  "CIP X10 Y0 I1=0 J1=-10 K1=0\nCYCLE977(101, 0, , 1, 20)\nG1 X20\n",
                                  siemens());
  ASSERT_EQ(blocks.size(), 4u);
  const Block& tilted = blocks[1];  // a half circle of radius 10 about the origin, in the plane y = z
  EXPECT_TRUE(tilted.isArc());
  EXPECT_TRUE(tilted.center.isZero(1e-9)) << tilted.center.transpose();
  EXPECT_NEAR(tilted.radius, 10.0, 1e-9);
  EXPECT_NEAR(tilted.length(), M_PI * 10.0, 1e-9);
  EXPECT_TRUE(tilted.pointAt(tilted.length() / 2).isApprox(Eigen::Vector3d(0, 7.0710678118654755, 7.0710678118654755), 1e-9));
  EXPECT_NEAR(std::abs(tilted.normal.dot(Eigen::Vector3d(0, 1, -1).normalized())), 1.0, 1e-12);
  const Block& back = blocks[2];  // CIP stays in force: back under the X axis through (0, -10, 0)
  EXPECT_TRUE(back.pointAt(back.length() / 2).isApprox(Eigen::Vector3d(0, -10, 0), 1e-9));
  EXPECT_EQ(errorOf("G0 X10\nCIP X-10 I1=0 F100\n", siemens()).rfind("line 2: CIP: the start, the intermediate point and the end are on one line", 0), 0u);
  EXPECT_EQ(errorOf("G0 X10\nCIP X-10 Y3 F100\n", siemens()).rfind("line 2: CIP needs its intermediate point", 0), 0u);
  std::istringstream text("G1 F100 X1\nCYCLE977(101, 0, , 1, 20)\nCYCLE978(0)\nG1 X2\n");
  GcodeReader reader(text, siemens());
  Block block;
  int count = 0;
  while (reader.next(block)) ++count;
  EXPECT_EQ(count, 2);
  EXPECT_EQ(reader.stats().unknownWordCounts.at("CYCLE977"), 1);
  EXPECT_EQ(errorOf("G1 F100 X1\nPOCKET3(10, 0, 1, -5)\n", siemens()).rfind("line 2: 'POCKET3' (an 840D standard cycle", 0), 0u);
}

// Mutations of a program in the 840D's frames, swivel and arcs through a point are read or refused with an
// InputError, never a crash, a non-finite point or an endless run.
TEST(SiemensFrames, FuzzedFramesAreReadOrRefused) {
  const std::string seed =
      "G17 G0 X0 Y0 Z10\nTRANS X10 Y5\nAROT RPL=30\nG1 F100 X10 Y0\nATRANS X1\nSCALE X2 Y2\nG1 X5 Y5\n"
      "G2 X10 Y0 I0 J-5\nMIRROR X0\nG1 X5 Y0\nG3 X5 Y10 CR=5\nROT Y-90\nG1 X100 Z20\nROT\n"
      "CYCLE800(1,\"TC\",0,57,0,0,5,10,30,45,0,0,1,1)\n"
      "G0 X0 Y0 Z20\nCIP X10 Y10 Z0 I1=5 J1=8 K1=3\nCYCLE800()\nG0 X0\n";
  ReaderOptions options = siemens();
  ASSERT_GT(readProgram(seed, options).size(), 8u);
  hsm::test::expectReadAndRefused(seed, "TRANSROTCYLEMIP()XYZIJK0123456789.-,=\n ", options, 48);
}

// Fundamentals, "Inch or metric dimensions": G70 / G71 change the unit of lengths only, F stays in the basic
// system (metric here; an inch machine starts in G700); G700 / G710 change both. Elsewhere G20 / G21 change both.
TEST(SiemensLanguage, InchLengthsAndTheBasicSystemsFeed) {
  const auto lengths = readProgram("G70 G1 X1 F100\nG700 X2 F100\nG71 X10 F100\nG710 X20 F100\n", siemens());
  ASSERT_EQ(lengths.size(), 4u);
  EXPECT_DOUBLE_EQ(lengths[0].end.x(), 25.4);
  EXPECT_DOUBLE_EQ(lengths[0].feed, 100.0 / 60.0);         // G70: F100 mm/min
  EXPECT_DOUBLE_EQ(lengths[1].feed, 100.0 * 25.4 / 60.0);  // G700: F100 inch/min
  EXPECT_DOUBLE_EQ(lengths[2].end.x(), 10.0);
  EXPECT_DOUBLE_EQ(lengths[2].feed, 100.0 * 25.4 / 60.0);  // G71 after G700: F still in inches
  EXPECT_DOUBLE_EQ(lengths[3].feed, 100.0 / 60.0);
  ReaderOptions inchMachine = siemens();
  inchMachine.conventions.powerOnCodes = "G700";
  const auto inch = readProgram("G70 G1 X1 F10\n", inchMachine);
  EXPECT_DOUBLE_EQ(inch[0].feed, 10.0 * 25.4 / 60.0);
  ReaderOptions linuxcnc;
  EXPECT_DOUBLE_EQ(readProgram("G20\nG1 X1 F10\n", linuxcnc)[0].feed, 10.0 * 25.4 / 60.0);
}
