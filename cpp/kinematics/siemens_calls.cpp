// The 840D's subprograms (SiemensProgram's, internal): found in their files, called with their PROC's parameters
// and passes, left by RET / M17; the values of the variables in a cycle call's arguments.
#include "kinematics/siemens_program.hpp"

#include "common/text.hpp"
#include "kinematics/gcode_interpreter.hpp"
#include "kinematics/siemens_text.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::kinematics::detail {

using namespace std::string_view_literals;
using namespace siemens_text;

namespace {
constexpr size_t kProcLines = 200;  // a subprogram file's PROC line is among its first lines (after its header)
}  // namespace

const SiemensProgram::Subprogram* SiemensProgram::subprogram(const std::string& called, long n, bool required) {
  const auto known = subprograms_.find(called);
  if (known != subprograms_.end()) return &known->second;
  auto missing = missing_.find(called);
  if (missing == missing_.end()) {
    std::string lower = called;
    for (char& c : lower) c = asciiLower(c);
    std::vector<std::string> names = {called + ".SPF", called + ".spf", lower + ".spf", called + ".MPF",
                                      called + ".mpf", lower + ".mpf", "_N_" + called + "_SPF", "_N_" + called + "_MPF"};
    std::string looked;
    for (const std::string& folder : options_.subroutineFolders) {
      for (const std::string& file : names) {
        const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + file;
        const long index = files_.load(path, file, n);
        if (index < 0) continue;
        Subprogram found{LineCursor{static_cast<size_t>(index), 0}, {}};
        const KeptFile& kept = files_[static_cast<size_t>(index)];
        for (size_t i = 0; i < std::min(kProcLines, kept.lines.size()); ++i) {
          const std::string_view statement = body(kept.lines[i].text).statement;
          if (keywordOf(statement) != "PROC") continue;
          found.parameters = procParameters(statement.data() + 4, statement.data() + statement.size(),
                                            kept.lines[i].number);
          found.start = LineCursor{static_cast<size_t>(index), i + 1};
          break;
        }
        return &(subprograms_[called] = found);
      }
      looked += (looked.empty() ? "" : ", ") + (folder.empty() ? std::string(".") : folder);
    }
    missing = missing_.emplace(called, looked.empty() ? std::string("no folder given") : "in " + looked).first;
  }
  if (!required || options_.passMissingCalls) return nullptr;
  const std::string nearest = nearestSiemensKeyword(called);
  fail(n, "subprogram " + called + " is not found (looked for " + called + ".SPF, " + called + ".MPF and _N_" + called +
              "_SPF " + missing->second + "; the control stops here too, alarm 14011): put " + called +
              ".SPF beside the program or give its folder" +
              (nearest.empty() ? std::string() : "; or is it a misspelt " + nearest + "?"));
}

bool SiemensProgram::callStatement(const std::string& called, std::string_view statement, long n) {
  const char* p = statement.data() + called.size();
  const char* end = statement.data() + statement.size();
  const char* q = p;
  skipBlanks(q, end);
  if ((q < end && *q == '=') || called == "DEF"sv) return false;  // an assignment, a declaration
  const bool lNumber = called[0] == 'L' && std::all_of(called.begin() + 1, called.end(), [](char c) { return isAsciiDigit(c); });
  if (!lNumber && (variables_.isVariable(called) || isSiemensKeyword(called))) return false;
  std::string_view arguments;
  p = q;
  if (p < end && *p == '(') arguments = parenthesised(p, end, n);
  const double value = passesOf(p, end, n);
  if (!(value >= 1 && value == std::floor(value) && value <= static_cast<double>(options_.maxLoopIterations)))
    fail(n, called + " P" + number(value) + ": a call's passes are a whole number from 1 to " +
                std::to_string(options_.maxLoopIterations));
  const long passes = static_cast<long>(value);
  if (!endOfStatement(p, end))
    fail(n, "the call of " + called + " shares its block with '" + std::string(trimmed(std::string_view(p, end - p)).substr(0, 24)) +
                "': put the call on a block of its own (with P=<passes>)");
  // A standard cycle is a subprogram of the control's cycle folder: called when given, else named by the
  // interpreter as motion it does not model.
  const Subprogram* target = subprogram(called, n, !isStandardCycle(called));
  if (target == nullptr) return false;  // missing, and to be skipped: the interpreter counts it
  call(*target, called, arguments, passes, n);
  return true;
}

void SiemensProgram::call(const Subprogram& target, const std::string& called, std::string_view arguments, long passes,
                          long n) {
  if (static_cast<int>(frames_.size()) >= kMaxSiemensCallDepth)
    fail(n, called + ": calls nested more than " + std::to_string(kMaxSiemensCallDepth) +
                " levels deep (the 840D's limit; a subprogram that calls itself without end?)");
  Frame frame{target.start, cursor_, passes - 1, n, {}, {}};
  const std::vector<std::string_view> parts = commaParts(arguments);
  if (parts.size() > target.parameters.size())
    fail(n, called + " takes " + std::to_string(target.parameters.size()) + " parameters (its PROC line names them), the "
                "call gives " + std::to_string(parts.size()));
  for (size_t i = 0; i < target.parameters.size(); ++i) {
    double value = 0.0;  // a parameter the call leaves out is 0
    if (i < parts.size()) {
      const std::string_view argument = trimmed(parts[i]);
      if (!argument.empty() && argument.front() != '"') {
        const char* a = argument.data();
        const char* e = a + argument.size();
        value = variables_.evaluate(a, e, n);
        if (!endOfStatement(a, e)) fail(n, called + ": argument " + std::to_string(i + 1) + " ('" + std::string(argument) +
                                               "') is not an expression");
      }
    }
    frame.arguments.emplace_back(target.parameters[i], value);
  }
  variables_.enterCall();
  for (const auto& [parameter, value] : frame.arguments) variables_.declareLocal(parameter, value);
  frames_.push_back(std::move(frame));
  cursor_ = target.start;
}

void SiemensProgram::leave() {
  Frame& frame = frames_.back();
  variables_.leaveCall();
  if (frame.repeatsLeft > 0) {
    --frame.repeatsLeft;
    frame.structures.clear();
    variables_.enterCall();
    for (const auto& [parameter, value] : frame.arguments) variables_.declareLocal(parameter, value);
    cursor_ = frame.start;
    return;
  }
  cursor_ = frame.returnTo;
  frames_.pop_back();
}

std::string_view SiemensProgram::computedCycleArguments(std::string_view statement, long n) {
  const size_t at = statement.find("CYCLE");
  if (at == std::string_view::npos) return statement;
  size_t open = at + 5;
  while (open < statement.size() && isAsciiDigit(statement[open])) ++open;
  if (open == at + 5 || open >= statement.size() || statement[open] != '(') return statement;
  const char* p = statement.data() + open;
  const char* end = statement.data() + statement.size();
  const std::string_view list = parenthesised(p, end, n);
  const std::vector<std::string_view> parts = commaParts(list);
  const bool named = std::any_of(parts.begin(), parts.end(), [](std::string_view part) {
    part = trimmed(part);
    return !part.empty() && part.front() != '"' && std::any_of(part.begin(), part.end(), [](char c) { return isAsciiLetter(c); });
  });
  if (!named) return statement;
  // R parameters and variables in a cycle's arguments (CYCLE81(R1, 0, R2+1, …)): their values, as the control
  // passes them; a name that is neither stays, for the cycle to name
  cycleCall_.assign(statement.substr(0, open + 1));
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string_view part = trimmed(parts[i]);
    if (i > 0) cycleCall_ += ',';
    if (part.empty() || part.front() == '"' || std::none_of(part.begin(), part.end(), [](char c) { return isAsciiLetter(c); })) {
      cycleCall_.append(part);
      continue;
    }
    try {
      const char* a = part.data();
      const char* e = a + part.size();
      const double value = variables_.evaluate(a, e, n);
      if (!endOfStatement(a, e)) throw ParseError(n, "not an expression");
      cycleCall_ += number(value);
    } catch (const ParseError&) {
      cycleCall_.append(part);
    }
  }
  cycleCall_ += ')';
  cycleCall_.append(p, static_cast<size_t>(end - p));
  return cycleCall_;
}

}  // namespace hsm::kinematics::detail
