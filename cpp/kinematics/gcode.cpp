#include "kinematics/gcode.hpp"

#include "common/text.hpp"
#include "kinematics/gcode_interpreter.hpp"
#include "kinematics/macro_program.hpp"
#include "kinematics/ngc_program.hpp"
#include "kinematics/siemens_program.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>
#include <string_view>

namespace hsm::kinematics {

std::string printable(std::string_view text) {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) {
      out += c;
    } else {
      out += "\\x";
      out += digits[byte >> 4];
      out += digits[byte & 15];
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------------------
// Block geometry

double Block::length() const {
  if (!isArc()) return (end - start).norm();
  const double along = normal.dot(end - start);
  return std::hypot(radius * std::abs(sweep), along);
}

namespace {
Eigen::Vector3d rotated(const Eigen::Vector3d& v, const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis) * v;
}
}  // namespace

Eigen::Vector3d Block::tangent(bool atEnd) const {
  if (!isArc()) {
    const Eigen::Vector3d d = end - start;
    const double n = d.norm();
    return n > 0.0 ? Eigen::Vector3d(d / n) : Eigen::Vector3d::UnitX();
  }
  Eigen::Vector3d radial = start - center;
  radial -= normal.dot(radial) * normal;
  if (atEnd) radial = rotated(radial, normal, sweep);
  const Eigen::Vector3d around = (sweep >= 0 ? 1.0 : -1.0) * normal.cross(radial).normalized();
  const Eigen::Vector3d t = around * radius * std::abs(sweep) + normal * normal.dot(end - start);
  return t.normalized();
}

Eigen::Vector3d Block::pointAt(double distance) const {
  const double total = length();
  const double f = total > 0.0 ? std::clamp(distance / total, 0.0, 1.0) : 0.0;
  if (!isArc()) return start + f * (end - start);
  Eigen::Vector3d radial = start - center;
  const double offset = normal.dot(radial);
  radial -= offset * normal;
  return center + offset * normal + rotated(radial, normal, f * sweep) + f * normal.dot(end - start) * normal;
}

// ---------------------------------------------------------------------------------------------------------
// The reader: lines (gcode_lexer) through the modal interpreter (gcode_interpreter)

struct GcodeReader::Impl {
  detail::LineSource source;
  detail::Line line;
  detail::Interpreter interpreter;
  Dialect dialect;
  std::unique_ptr<detail::NgcProgram> ngc;      // LinuxCNC's O-words (and grbl's programs)
  std::unique_ptr<detail::MacroProgram> macro;  // Fanuc's and Haas's subprograms and Macro B
  double positions[3][3] = {};                  // for Macro B's position variables
  std::unique_ptr<detail::SiemensProgram> siemens;  // the 840D's variables, jumps, loops and subprograms
  long lineNumber = 0;

  Impl(std::istream& input, const ReaderOptions& options)
      : source(input), interpreter(options), dialect(options.conventions.dialect) {
    if (dialect == Dialect::LinuxCnc || dialect == Dialect::Grbl)
      ngc = std::make_unique<detail::NgcProgram>(source, detail::NgcOptions{options.subroutineFolders,
                                                                            options.maxLoopIterations});
    if (isFanucFamily(dialect)) {
      macro = std::make_unique<detail::MacroProgram>(
          source, detail::MacroOptions{options.subroutineFolders, options.maxLoopIterations, dialect == Dialect::Haas});
      macro->setPositions(positions);
    }
    if (dialect == Dialect::Siemens840D)
      siemens = std::make_unique<detail::SiemensProgram>(
          source, detail::SiemensOptions{options.subroutineFolders, options.maxLoopIterations, options.skipUnknownMotion});
    if (!options.conventions.powerOnCodes.empty()) {  // the control's state before the program's first line
      Block ignored;
      line.parse(options.conventions.powerOnCodes, 0);
      if (interpreter.interpret(line, 0, ignored) || interpreter.takeQueued(ignored))
        throw InputError("power-on codes '" + printable(options.conventions.powerOnCodes) +
                         "' move the machine: give only modal G words (\"G0 G17 G90 G94 G21 G98\")");
    }
  }

  // The next line to run: through the dialect's program flow, or as the file has it.
  bool nextLine(std::string_view& raw, long& number) {
    if (ngc) return ngc->next(raw, number);
    if (macro) return macro->next(raw, number);
    if (siemens) return siemens->next(raw, number);
    if (!source.next(raw)) return false;
    number = ++lineNumber;
    return true;
  }

  bool next(Block& block) {
    if (interpreter.takeQueued(block)) return true;  // the rest of a canned cycle's moves
    std::string_view raw;
    long number = 0;
    while (nextLine(raw, number)) {
      if (number <= detail::kDialectLines) detail::refuseOtherLanguages(raw, number);
      ++interpreter.stats().lines;
      bool moved = false;
      try {
        line.parse(raw, number);
        if (line.wordCount == 0 && line.keywords.empty()) continue;
        moved = interpreter.interpret(line, number, block);
      } catch (const ParseError& error) {
        const std::string file = subprogramFile();
        if (file.empty()) throw;
        throw ParseError(error.line(), error.message() + " (in " + file + ")");  // a line of a subprogram file
      }
      if (macro) interpreter.positions(positions);
      if (moved) return true;
    }
    return false;
  }

  std::string subprogramFile() const {
    return ngc ? ngc->lastFileName() : macro ? macro->lastFileName() : siemens ? siemens->lastFileName() : "";
  }
};

GcodeReader::GcodeReader(std::istream& input, ReaderOptions options)
    : impl_(std::make_unique<Impl>(input, options)) {}
GcodeReader::~GcodeReader() = default;
bool GcodeReader::next(Block& block) { return impl_->next(block); }
const ReaderStats& GcodeReader::stats() const { return impl_->interpreter.stats(); }

std::vector<Block> readProgram(const std::string& text, const ReaderOptions& options) {
  std::istringstream stream(text);
  GcodeReader reader(stream, options);
  std::vector<Block> blocks;
  Block block;
  while (reader.next(block)) blocks.push_back(block);
  return blocks;
}

}  // namespace hsm::kinematics
