// The G-code dialects the reader takes, and what a control assumes where a program says nothing: its
// power-on modal state, how it reads a number written without a decimal point, where the program's zero
// lies in machine coordinates. A machine file chooses them (machine.hpp); the reader applies them.
#pragma once

#include <Eigen/Core>

#include <string>

namespace hsm::kinematics {

enum class Dialect {
  LinuxCnc,     // rs274ngc: #parameters, [expressions], O-word subroutines and loops
  Grbl,         // read as LinuxCNC's (a subset of it)
  Siemens840D,  // the 840D's words (CYCLE832, TRAORI, A3 B3 C3, CR=…); no O-word language
  Fanuc,        // Fanuc 0i/30i: O-numbers, Macro B (#1, IF/GOTO, WHILE/DO/END, G65), M98/M99 subprograms
  Haas,         // Haas NGC: Fanuc's language and M97 local subprograms; G187 smoothing, G234 tool centre point
};

struct ControlConventions {
  Dialect dialect = Dialect::LinuxCnc;
  // G words the control is in before the program's first line (a Fanuc's parameters 3402/3401, a Haas's
  // settings), as one line: "G0 G17 G90 G94 G21 G98". Empty: the reader's own start (no motion mode).
  std::string powerOnCodes;
  // Fanuc's DPI parameter off: a dimension written without a point counts least input increments
  // (X100 is 0.1 mm in G21, 0.01 inch in G20); on (and on a Haas): whole millimetres or inches.
  bool leastIncrementInput = false;
  // The program's zero (its work offset) in machine coordinates: a G53 move and G28's return to the
  // reference point (machine zero) go where the machine is, not where the program's coordinates are.
  Eigen::Vector3d workOffset = Eigen::Vector3d::Zero();
  // mm: the contour error a look-ahead mode switched on by the program allows (Fanuc G05.1 Q1 / G08 P1, Haas
  // G187 without E): the machine file's corner tolerance.
  double smoothingTolerance = 0.01;
};

inline constexpr double kLeastIncrementMm = 0.001;    // Fanuc IS-B, metric input
inline constexpr double kLeastIncrementInch = 0.0001;  // Fanuc IS-B, inch input

std::string dialectName(Dialect dialect);  // "linuxcnc", "grbl", "siemens-840d", "fanuc", "haas"
// The dialect of a name as dialectName gives it; InputError naming `origin` and the names that exist.
Dialect dialectFromName(const std::string& name, const std::string& origin);
// Fanuc or Haas: the Macro B language and M98/M99 subprograms.
inline bool isFanucFamily(Dialect d) { return d == Dialect::Fanuc || d == Dialect::Haas; }

}  // namespace hsm::kinematics
