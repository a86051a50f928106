// LinuxCNC's language: parameters, expressions and O-word flow, read as LinuxCNC 2.9's rs274ngc reads them
// (LinuxCNC documentation, "G-code overview": parameters, expressions, operators, functions; "O codes").
#include "kinematics/gcode.hpp"

#include "support/gcode_errors.hpp"
#include "support/mutation.hpp"
#include "support/reader_fuzz.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

using namespace hsm::kinematics;
using hsm::test::errorOf;

namespace {

std::vector<double> xs(const std::vector<Block>& blocks) {
  std::vector<double> out;
  for (const Block& b : blocks) out.push_back(b.end.x());
  return out;
}
}  // namespace

// "Numbered parameters", "Named parameters": a setting takes effect after the line is read.
TEST(NgcLanguage, ParametersAreSetAfterTheLineIsRead) {
  const auto blocks = readProgram("#1 = 5\n#<depth> = -2\nG1 X#1 Z#<depth> F600\n#1 = 7 X[#1 + 1]\nG1 X#1\n");
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].end, Eigen::Vector3d(5, 0, -2));
  EXPECT_DOUBLE_EQ(blocks[1].end.x(), 6.0);  // #1 = 7 is applied after X[#1 + 1] was read
  EXPECT_DOUBLE_EQ(blocks[2].end.x(), 7.0);
}

// "Operator precedence": ** first, then * / MOD, then + -, then comparisons, then AND OR XOR; left to right.
TEST(NgcLanguage, ExpressionsFollowLinuxCncsPrecedenceAndFunctions) {
  struct Case {
    const char* expression;
    double value;
  };
  const Case cases[] = {{"[1 + 2 * 3]", 7.0},          {"[2 ** 3 * 2]", 16.0},     {"[10 - 4 - 3]", 3.0},
                        {"[-7 MOD 3]", 2.0},           {"[1 + 2 GT 2]", 1.0},      {"[2 + [1 LT 2 AND 3 LT 2]]", 2.0},
                        {"[1 XOR 0]", 1.0},            {"[SQRT[16] + ABS[-2]]", 6.0}, {"[ATAN[1]/[1]]", 45.0},
                        {"[ROUND[2.5] + FIX[-1.5] + FUP[1.2]]", 3.0 - 2.0 + 2.0}, {"[SIN[30] * 2]", 1.0},
                        {"-[2 + 1]", -3.0},            {"[EXP[0] + LN[1]]", 1.0},  {"[[1 + 1] * [2 + 2]]", 8.0}};
  for (const Case& c : cases) {
    const auto blocks = readProgram(std::string("G1 X") + c.expression + " F600\n");
    ASSERT_EQ(blocks.size(), 1u) << c.expression;
    EXPECT_NEAR(blocks[0].end.x(), c.value, 1e-12) << c.expression;
  }
  EXPECT_NEAR(readProgram("G1 X sin[90] F600\n")[0].end.x(), 1.0, 1e-12);  // a function as a word's value
  EXPECT_NEAR(readProgram("#1=2\n#2=1\nG1 X##2 F600\n")[0].end.x(), 2.0, 1e-12);  // ##2 is #[#2]
}

TEST(NgcLanguage, ExistsAndGlobalsAcrossSubroutines) {
  const auto blocks = readProgram(
      "o<set> sub\n#<_g> = 3\n#<local> = 1\no<set> endsub\n"
      "o<set> call\nG1 X#<_g> Y[EXISTS[#<local>]] F600\n");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].end, Eigen::Vector3d(3, 0, 0));  // the sub's local is gone after its call
}

// "Subroutines": #1 … #30 are the call's arguments and are restored after it; o<name> return [value] sets
// #<_value>.
TEST(NgcLanguage, SubroutinesTakeArgumentsAndRestoreTheCallersParameters) {
  const auto blocks = readProgram(
      "#1 = 100\n"
      "o100 sub\n  G1 X[#1 + #2] F600\n  o100 return [#1 * 2]\n  G1 X999\no100 endsub\n"
      "o100 call [1] [2]\nG1 Y#<_value> X#1\n");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_DOUBLE_EQ(blocks[0].end.x(), 3.0);
  EXPECT_EQ(blocks[1].end, Eigen::Vector3d(100, 2, 0));
}

// Lines outside loops and calls stream through (not kept); a call after them still finds its subroutine, a
// call before its definition reads ahead to it, and both come back to the line after the call.
TEST(NgcLanguage, CallsComeBackAroundStreamedLines) {
  EXPECT_EQ(xs(readProgram("o1 sub\nG1 X#1\no1 endsub\nG1 X1 F600\no2 repeat [2]\nG1 X2\nG1 X3\no2 endrepeat\n"
                           "G1 X4\no1 call [5]\nG1 X6\no1 call [7]\n")),
            (std::vector<double>{1, 2, 3, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(xs(readProgram("G1 X1 F600\no9 call [2]\nG1 X3\nM2\no9 sub\nG1 X#1\no9 endsub\n")),
            (std::vector<double>{1, 2, 3}));  // the definition met after the call is skipped, as any definition
}

// "Looping": while/endwhile, do/while, repeat/endrepeat, break and continue.
TEST(NgcLanguage, LoopsRunAsManyTimesAsTheirConditionsSay) {
  EXPECT_EQ(xs(readProgram("#1=0\no1 while [#1 LT 3]\n#1=[#1+1]\nG1 X#1 F600\no1 endwhile\nG1 X9\n")),
            (std::vector<double>{1, 2, 3, 9}));
  EXPECT_EQ(xs(readProgram("#1=5\no2 do\nG1 X#1 F600\n#1=[#1+1]\no2 while [#1 LT 3]\n")), (std::vector<double>{5}));
  EXPECT_EQ(xs(readProgram("#1=0\no3 repeat [4]\n#1=[#1+1]\nG1 X#1 F600\no3 endrepeat\n")),
            (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(xs(readProgram("#1=0\no4 while [1]\n#1=[#1+1]\no5 if [#1 EQ 2]\no4 continue\no5 endif\n"
                           "G1 X#1 F600\no6 if [#1 GE 4]\no4 break\no6 endif\no4 endwhile\nG1 X0\n")),
            (std::vector<double>{1, 3, 4, 0}));
  EXPECT_TRUE(readProgram("o7 repeat [0]\nG1 X1 F600\no7 endrepeat\n").empty());
}

// "Conditional": if / elseif / else / endif, the first true branch only.
TEST(NgcLanguage, ConditionsRunTheFirstTrueBranch) {
  const char* program = "o1 if [#1 EQ 1]\nG1 X1 F600\no1 elseif [#1 EQ 2]\nG1 X2 F600\no1 else\nG1 X3 F600\no1 endif\n";
  for (int value = 1; value <= 3; ++value)
    EXPECT_EQ(xs(readProgram("#1=" + std::to_string(value) + "\n" + program)), (std::vector<double>{double(value)}));
}

TEST(NgcLanguage, SubroutineFilesAreFoundInTheFoldersGiven) {
  const auto folder = std::filesystem::temp_directory_path() / "hsm_ngc_subs";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "spiral.ngc") << "o<spiral> sub\no1 repeat [#1]\nG91 G1 X1 F600\no1 endrepeat\nG90\no<spiral> endsub\n";
  ReaderOptions options;
  options.subroutineFolders = {"/nonexistent", folder.string()};
  EXPECT_EQ(xs(readProgram("G0 X0\no<spiral> call [3]\nG1 X0\n", options)), (std::vector<double>{1, 2, 3, 0}));
  const std::string missing = errorOf("o<nowhere> call\n", options);
  EXPECT_NE(missing.find("line 1: o<nowhere> call: no subroutine o<nowhere> in the program, nor a file nowhere.ngc"),
            std::string::npos) << missing;
  EXPECT_NE(missing.find(folder.string() + "/nowhere.ngc"), std::string::npos) << missing;
  std::filesystem::remove_all(folder);
}

TEST(NgcLanguage, AHeidenhainProgramIsRefusedInOneLineThatSaysWhatItIs) {
  const std::string error = errorOf("0 BEGIN PGM 1234 MM\n1 BLK FORM 0.1 Z X-86 Y-75 Z-61\n");
  EXPECT_EQ(error.rfind("line 1: this is a Heidenhain conversational (Klartext) program", 0), 0u) << error;
}

TEST(NgcLanguage, PlainProgramsAndTheSiemensDialectAreReadAsBefore) {
  const std::string plain = "G1 X1 F600\nO1234\nG1 X2 ; comment with # and [\n";
  EXPECT_EQ(xs(readProgram(plain)), (std::vector<double>{1, 2}));
  ReaderOptions siemens;
  siemens.conventions.dialect = Dialect::Siemens840D;
  EXPECT_NE(errorOf("#1=2\n", siemens).find("unexpected character '#'"), std::string::npos);
}

// Bounded and named: endless loops, runaway recursion, absurd values, missing ends.
TEST(NgcLanguage, BadProgramsAreRefusedNamingTheLine) {
  struct Case {
    const char* program;
    const char* message;
  };
  const Case cases[] = {
      {"o1 while [1]\no1 endwhile\n", "line 1: o1 has looped 10000000 times"},
      {"o1 repeat [10 ** 12]\no1 endrepeat\n", "line 2: o1 has looped 10000000 times"},
      {"o<r> sub\no<r> call\no<r> endsub\no<r> call\n", "subroutines nested more than 50 deep"},
      {"G1 X[1/0] F600\n", "line 1: division by zero"},
      {"G1 X#<nope> F600\n", "line 1: #<nope> is read before it is set"},
      {"G1 X#<_nope> F600\n", "line 1: #<_nope> is read before it is set"},
      {"G1 X#9999 F600\n", "line 1: #9999 is not a parameter"},
      {"G1 X[SQRT[-1]] F600\n", "line 1: SQRT[-1]: the argument must not be negative"},
      {"G1 X[2 ** 5000] F600\n", "line 1: an expression's value is not a finite number"},
      {"#1=[10 ** 300]\nG1 X[#1 * #1 * #1] F600\n", "line 2: an expression's value is not a finite number"},
      {"#1=[10 ** 300]\nG1 X#1 F600\n", "is out of range"},
      {"G1 X[1 + 2 F600\n", "line 1: 'f' is not an operator"},
      {"o1 while [1]\nG1 X1 F600\n", "line 1: o1 is not closed before the program ends"},
      {"o1 if [0]\nG1 X1 F600\n", "line 1: o1 has no endif"},
      {"o2 call\n", "line 1: o2 call: the program has no o2 sub"},
      {"o3 frobnicate\n", "line 1: 'frobnicate' after o3 is not an O-word"},
      {"o4 endwhile\n", "line 1: o4 endwhile without its while"},
      {"o5 endsub\n", "line 1: o5 endsub outside a call of o5"},
      {"G1 X#<_hal[axis.0.pos]> F600\n", "line 1: #<_hal[axis.0.pos]> reads the machine's HAL"},
      {"#5 G1 X1\n", "line 1: a parameter stands alone"},
      {"G1 X[1 FOO 2] F600\n", "line 1: 'foo' is not an operator"},
  };
  for (const Case& c : cases) {
    const std::string error = errorOf(c.program);
    EXPECT_NE(error.find(c.message), std::string::npos) << c.program << " gave: " << error;
  }
}

TEST(NgcLanguage, FuzzedProgramsAreReadOrRefusedNeverCrash) {
  const std::string seed =
      "#1=2\n#<_d>=[#1*-1.5]\no1 sub\nG1 X[#1+1] Z#<_d> F600\no1 return [#1]\no1 endsub\n"
      "#2=0\no2 while [#2 LT 3]\n#2=[#2+1]\no3 if [#2 EQ 2]\no2 continue\no3 else\no1 call [#2]\no3 endif\n"
      "o2 endwhile\no4 repeat [2]\nG91 G1 X1\nG90\no4 endrepeat\nG1 X[ATAN[1]/[1] MOD 7] Y[SQRT[#<_value>+2]]\n";
  const std::string alphabet = "#<>[]=o0123456789.-+*/ \nGXYZF_abcdefghilnoprstuw";
  ReaderOptions bounded;  // a mutated loop condition loops for ever: stopped after 1000 turns
  bounded.maxLoopIterations = 1000;
  ASSERT_EQ(readProgram(seed, bounded).size(), 5u);  // two calls, two repeats, the last line
  hsm::test::expectReadAndRefused(seed, alphabet, bounded, 7);
}
