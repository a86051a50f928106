#include "kinematics/gcode.hpp"

#include "common/text.hpp"

#include <Eigen/Geometry>
#include <fast_float/fast_float.h>

#include <algorithm>
#include <array>
#include <cstring>
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
// Lines from a stream, read in large chunks

namespace {

class LineSource {
public:
  explicit LineSource(std::istream& input) : input_(input) { buffer_.reserve(kChunk * 2); }

  // The next line without its end-of-line characters; false at the end. A line longer than
  // kMaxLineLength is refused as soon as that many characters have come without a line end.
  bool next(std::string_view& line) {
    size_t searched = position_;
    for (;;) {
      const size_t newline = buffer_.find('\n', searched);
      if (newline != std::string::npos && newline - position_ <= kMaxLineLength) {
        line = trimmed(position_, newline);
        position_ = newline + 1;
        ++lines_;
        return true;
      }
      if (buffer_.size() - position_ > kMaxLineLength)
        throw ParseError(lines_ + 1, "the line is longer than " + std::to_string(kMaxLineLength) +
                                         " characters: a G-code block is one line (is this a G-code file?)");
      searched = buffer_.size() - position_;  // as an offset: refill() moves the unread part to the front
      if (eof_) {
        if (position_ >= buffer_.size()) return false;
        line = trimmed(position_, buffer_.size());
        position_ = buffer_.size();
        ++lines_;
        return true;
      }
      refill();
    }
  }

private:
  static constexpr size_t kChunk = 1 << 20;

  std::string_view trimmed(size_t from, size_t to) const {
    if (to > from && buffer_[to - 1] == '\r') --to;
    return std::string_view(buffer_.data() + from, to - from);
  }

  void refill() {
    buffer_.erase(0, position_);
    position_ = 0;
    const size_t old = buffer_.size();
    buffer_.resize(old + kChunk);
    input_.read(buffer_.data() + old, kChunk);
    const auto got = static_cast<size_t>(input_.gcount());
    buffer_.resize(old + got);
    if (got == 0 || !input_) eof_ = true;
  }

  std::istream& input_;
  std::string buffer_;
  size_t position_ = 0;
  long lines_ = 0;
  bool eof_ = false;
};

// ---------------------------------------------------------------------------------------------------------
// Words of one line

struct Word {
  char letter;
  double value;
  std::string_view text;  // as written, for messages
};

struct Keyword {
  std::string_view name;       // upper-cased copy lives in Line::upper
  std::string_view arguments;  // inside ( ), for calls
  bool hasValue = false;       // NAME=value
  double value = 0.0;
  bool call = false;
};

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c; }

class Line {
public:
  std::array<Word, 64> words{};
  int wordCount = 0;
  std::vector<Keyword> keywords;
  std::string upper;  // upper-cased copy of the line: keywords point into it

  // Splits `raw` into words and keywords; throws ParseError on malformed text.
  void parse(std::string_view raw, long number) {
    wordCount = 0;
    keywords.clear();
    upper.assign(raw);
    for (char& c : upper) c = hsm::kinematics::upper(c);
    const char* p = upper.data();
    const char* end = p + upper.size();
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p < end && *p == '/') ++p;  // block delete: the block runs (the switch is off)
    while (p < end) {
      const char c = *p;
      if (c == ' ' || c == '\t') {
        ++p;
      } else if (c == ';') {
        break;
      } else if (c == '(') {
        const char* close = static_cast<const char*>(std::memchr(p, ')', end - p));
        if (!close) throw ParseError(number, "comment '(' is not closed: add ')'");
        p = close + 1;
      } else if (c == '%' && wordCount == 0 && keywords.empty()) {
        break;  // program start/end marker
      } else if (isLetter(c)) {
        const char after = p + 1 < end ? p[1] : ' ';
        p = isLetter(after) || after == '_' || after == '=' ? keyword(p, end, number) : word(p, end, number);
      } else {
        throw ParseError(number, std::string("unexpected character '") + c + "' (byte " +
                                     std::to_string(static_cast<unsigned char>(c)) +
                                     "): G-code words are a letter and a number; is this a G-code file?");
      }
    }
  }

private:
  // A G-code number at p: an optional sign, digits with at most one point, no exponent, nan or inf, at
  // most kMaxWordValue. Returns the end of the number; `what` names the word in messages.
  const char* numberAt(const char* p, const char* end, double& value, std::string_view what, long number) {
    const char* digits = p < end && (*p == '+' || *p == '-') ? p + 1 : p;
    const char* token = p;  // what is quoted: up to the next blank, at most 24 characters
    while (token < end && token - p < 24 && *token != ' ' && *token != '\t') ++token;
    if (!(digits < end && (isDigit(*digits) || (*digits == '.' && digits + 1 < end && isDigit(digits[1])))))
      throw ParseError(number, "'" + std::string(what) + std::string(p, token) +
                                   "' is not a letter followed by a number (digits, an optional sign and point)");
    const char* from = *p == '+' ? p + 1 : p;
    const auto parsed = fast_float::from_chars(from, end, value, fast_float::chars_format::fixed);
    const char* stop = parsed.ptr;
    if (parsed.ec != std::errc() || (stop < end && (*stop == '.' || isDigit(*stop))))
      throw ParseError(number, "'" + std::string(what) + std::string(p, token) + "' is not a number");
    if (stop < end && (*stop == 'e' || *stop == 'E') && stop + 1 < end &&
        (isDigit(stop[1]) || ((stop[1] == '+' || stop[1] == '-') && stop + 2 < end && isDigit(stop[2]))))
      throw ParseError(number, "'" + std::string(what) + std::string(p, token) +
                                   "': G-code numbers have no exponent; write the number in full");
    if (!(std::abs(value) <= kMaxWordValue))
      throw ParseError(number, "'" + std::string(what) + std::string(p, std::min<size_t>(stop - p, 24)) +
                                   "' is out of range: words are at most " + std::to_string(long(kMaxWordValue)) +
                                   " in size");
    return stop;
  }

  const char* word(const char* p, const char* end, long number) {
    const char letter = *p;
    const char* start = p++;
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    double value = 0.0;
    const char* numberEnd = numberAt(p, end, value, std::string_view(start, p - start), number);
    p = numberEnd;
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p < end && *p == '=') {
      // R1=5, P3=… : a parameter assignment (Siemens R parameters): not a plain word.
      Keyword k;
      k.name = std::string_view(start, numberEnd - start);
      k.hasValue = true;
      p = assignment(p + 1, end, k, number);
      keywords.push_back(k);
      return p;
    }
    if (wordCount == static_cast<int>(words.size())) throw ParseError(number, "more than 64 words on one line");
    words[wordCount++] = Word{letter, value, std::string_view(start, numberEnd - start)};
    return p;
  }

  const char* keyword(const char* p, const char* end, long number) {
    const char* start = p;
    while (p < end && (isLetter(*p) || isDigit(*p) || *p == '_')) ++p;
    Keyword k;
    k.name = std::string_view(start, p - start);
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p < end && *p == '=') {
      k.hasValue = true;
      p = assignment(p + 1, end, k, number);
    } else if (p < end && *p == '(') {
      int depth = 0;
      const char* open = p;
      for (; p < end; ++p) {
        if (*p == '(') ++depth;
        if (*p == ')' && --depth == 0) break;
      }
      if (p == end) throw ParseError(number, "'" + std::string(k.name) + "(' is not closed: add ')'");
      k.call = true;
      k.arguments = std::string_view(open + 1, p - open - 1);
      ++p;
    }
    keywords.push_back(k);
    return p;
  }

  const char* assignment(const char* p, const char* end, Keyword& k, long number) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    const char* digits = p < end && (*p == '+' || *p == '-') ? p + 1 : p;
    const char* stop = p;
    if (digits < end && (isDigit(*digits) || *digits == '.')) {
      stop = numberAt(p, end, k.value, std::string(k.name) + "=", number);
      if (stop == end || *stop == ' ' || *stop == '\t' || *stop == ';') return stop;
    }
    // An expression or a variable (R1=R2*3): not evaluated; keep the name so it counts as unknown.
    k.hasValue = false;
    while (p < end && *p != ' ' && *p != '\t' && *p != ';') ++p;
    return p;
  }
};

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// The modal interpreter

struct GcodeReader::Impl {
  LineSource source;
  ReaderOptions options;
  ReaderStats stats;
  Line line;
  long lineNumber = 0;

  // Modal state
  Eigen::Vector3d position;
  int motion = -1;        // 0, 1, 2, 3; −1 before the first motion word
  int plane = 17;
  bool absolute = true;
  bool arcCentreAbsolute = false;
  double unit = 1.0;      // mm per program unit
  double feed = 0.0;      // mm/s
  PathMode pathMode = PathMode::Continuous;
  double tolerance = 0.0;
  double roundingTolerance = 0.0;  // from CYCLE832 or ADIS; used by G641/G642
  int jerkLimited = -1;

  Impl(std::istream& input, ReaderOptions o) : source(input), options(o), position(o.startPosition) {}

  void unknown(std::string_view word) {
    if (options.refuseUnknownWords)
      throw ParseError(lineNumber, "'" + std::string(word) + "' is not understood: remove it, or let unknown "
                                   "words be skipped (refuse_unknown_words off)");
    ++stats.unknownWords;
    auto it = stats.unknownWordCounts.find(std::string(word));
    if (it != stats.unknownWordCounts.end()) {
      ++it->second;
    } else if (stats.unknownWordCounts.size() < 50) {
      stats.unknownWordCounts.emplace(std::string(word), 1);
    }
  }

  bool next(Block& block) {
    std::string_view raw;
    while (source.next(raw)) {
      ++lineNumber;
      ++stats.lines;
      line.parse(raw, lineNumber);
      if (line.wordCount == 0 && line.keywords.empty()) continue;
      if (interpret(block)) {
        ++stats.motionBlocks;
        return true;
      }
    }
    return false;
  }

  // Applies one line; true when it produced a motion block.
  bool interpret(Block& block) {
    bool exactStopHere = false, dwell = false;
    int newMotion = -1;
    bool hasAxis[3] = {false, false, false}, hasOffset[3] = {false, false, false};
    double axis[3] = {0, 0, 0}, offset[3] = {0, 0, 0};
    double radiusWord = 0.0, pWord = -1.0, fWord = 0.0;
    bool hasRadius = false, g64 = false, hasFeed = false, hasP = false;

    for (const Keyword& k : line.keywords) {
      if (isFrameKeyword(k.name)) {
        unknown(k.name);  // frames are not simulated: the line is skipped
        return false;
      }
      keyword(k, radiusWord, hasRadius);
    }
    for (int i = 0; i < line.wordCount; ++i) {
      const Word& w = line.words[i];
      switch (w.letter) {
        case 'G': gWord(w, newMotion, exactStopHere, dwell, g64); break;
        case 'X': case 'Y': case 'Z': {
          const int a = w.letter - 'X';
          if (hasAxis[a]) throw ParseError(lineNumber, std::string("axis ") + w.letter + " given twice");
          hasAxis[a] = true;
          axis[a] = w.value;
          break;
        }
        case 'I': case 'J': case 'K': {
          const int a = w.letter - 'I';
          hasOffset[a] = true;
          offset[a] = w.value;
          break;
        }
        case 'F': fWord = w.value; hasFeed = true; break;
        case 'R': radiusWord = w.value; hasRadius = true; break;
        case 'P': pWord = w.value; hasP = true; break;
        case 'M': mWord(w); break;
        case 'T': ++stats.toolChanges; break;
        case 'N': case 'S': case 'D': case 'H': case 'Q': case 'L': break;  // no effect on the motion
        default: unknown(w.text);
      }
    }
    if (hasFeed && !dwell) {
      if (fWord <= 0.0 || !std::isfinite(fWord))
        throw ParseError(lineNumber, "feed rate F" + std::to_string(fWord) + " must be positive");
      feed = options.feedInMmPerSecond ? fWord * unit : fWord * unit / 60.0;
    }
    if (dwell) {
      const double seconds = pWord >= 0.0 ? pWord : hasFeed ? fWord : -1.0;  // LinuxCNC G4 P, Siemens G4 F
      if (hasP && pWord < 0.0)
        throw ParseError(lineNumber, "G4 P" + number(pWord) + ": a dwell lasts 0 s or more; write G4 P<seconds>");
      if (!(seconds >= 0.0)) throw ParseError(lineNumber, "G4 dwell needs its time: G4 P<seconds> (or F on the 840D)");
      stats.dwellTime += seconds;
    }
    if (g64) {
      if (pWord > 0.0) {
        pathMode = PathMode::Rounding;
        tolerance = pWord * unit;
      } else {
        pathMode = PathMode::Continuous;
        tolerance = 0.0;
      }
    }
    if (newMotion >= 0) motion = newMotion;

    const bool anyAxis = hasAxis[0] || hasAxis[1] || hasAxis[2];
    const bool anyOffset = hasOffset[0] || hasOffset[1] || hasOffset[2];
    if ((newMotion == 2 || newMotion == 3) && !anyAxis && !anyOffset && !hasRadius)
      throw ParseError(lineNumber, "G" + std::to_string(newMotion) + " without an end point or a centre: an arc needs "
                                   "X/Y/Z and I/J/K (or R); the line moves nothing");
    if (!anyAxis && !(anyOffset && (motion == 2 || motion == 3))) return false;
    if (dwell) return false;
    if (motion < 0) throw ParseError(lineNumber, "coordinates before any motion mode: start with G0 or G1");

    Eigen::Vector3d target = position;
    for (int a = 0; a < 3; ++a)
      if (hasAxis[a]) target[a] = absolute ? axis[a] * unit : position[a] + axis[a] * unit;

    block = Block{};
    block.start = position;
    block.end = target;
    block.line = lineNumber;
    block.pathMode = exactStopHere ? PathMode::ExactStop : pathMode;
    block.tolerance = tolerance;
    block.jerkLimited = jerkLimited;
    if (motion == 0) {
      block.motion = Motion::Rapid;
    } else {
      if (feed <= 0.0) throw ParseError(lineNumber, "no feed rate: program F before the first G1/G2/G3 move");
      block.feed = feed;
      block.motion = motion == 1 ? Motion::Linear : motion == 2 ? Motion::ArcClockwise : Motion::ArcCounterClockwise;
    }
    if (block.isArc()) {
      arc(block, offset, hasOffset, radiusWord, hasRadius);
    } else if ((target - position).squaredNorm() == 0.0) {
      return false;  // a move to where the tool already is
    }
    position = target;
    return true;
  }

  void gWord(const Word& w, int& newMotion, bool& exactStopHere, bool& dwell, bool& g64) {
    const long code = std::lround(w.value * 10.0);
    if (std::abs(w.value * 10.0 - code) > 1e-6) return unknown(w.text);
    switch (code) {
      case 0: case 10: case 20: case 30: newMotion = int(code / 10); break;
      case 40: dwell = true; break;
      case 90: exactStopHere = true; break;
      case 170: case 180: case 190: plane = int(code / 10); break;
      case 200: case 700: case 7000: unit = 25.4; break;  // G20; 840D G70/G700
      case 210: case 710: case 7100: unit = 1.0; break;   // G21; 840D G71/G710
      case 900: absolute = true; break;
      case 910: absolute = false; break;
      case 901: arcCentreAbsolute = true; break;
      case 911: arcCentreAbsolute = false; break;
      case 600: case 610: case 611: pathMode = PathMode::ExactStop; break;
      case 640: g64 = true; break;
      case 6410: case 6420: case 6430: case 6440: case 6450:
        pathMode = PathMode::Rounding;
        tolerance = roundingTolerance;
        break;
      // Accepted without effect on the simulated motion: cutter and length compensation, work offsets,
      // canned-cycle cancel, feed per minute, exact-stop windows, return modes, machine coordinates.
      case 400: case 410: case 420: case 430: case 431: case 490: case 530: case 540: case 550: case 560:
      case 570: case 580: case 590: case 800: case 940: case 980: case 990: case 6010: case 6020: case 6030:
      case 150: case 160: case 5000: case 5010:
        break;
      default: unknown(w.text);
    }
  }

  void mWord(const Word& w) {
    const long code = std::lround(w.value);
    if (code == 6) ++stats.toolChanges;
    const bool known = code == 0 || code == 1 || code == 2 || code == 3 || code == 4 || code == 5 || code == 6 ||
                       code == 7 || code == 8 || code == 9 || code == 30 || code == 17;
    if (!known) unknown(w.text);
  }

  // Siemens frame instructions: the coordinates on their line shift the frame, they do not move the tool.
  static bool isFrameKeyword(std::string_view name) {
    return name == "TRANS" || name == "ATRANS" || name == "ROT" || name == "AROT" || name == "SCALE" ||
           name == "ASCALE" || name == "MIRROR" || name == "AMIRROR";
  }

  void keyword(const Keyword& k, double& radiusWord, bool& hasRadius) {
    const std::string_view name = k.name;
    if (name == "SOFT") {
      jerkLimited = 1;
    } else if (name == "BRISK") {
      jerkLimited = 0;
    } else if (name == "CR" && k.hasValue) {
      radiusWord = k.value;
      hasRadius = true;
    } else if ((name == "ADIS" || name == "ADISPOS") && k.hasValue) {
      roundingTolerance = k.value * unit;
      if (pathMode == PathMode::Rounding) tolerance = roundingTolerance;
    } else if (name == "T") {
      ++stats.toolChanges;  // T="BALL4": a tool called by name
    } else if (name == "MSG") {
      // operator messages
    } else if (name == "CYCLE832" && k.call) {
      cycle832(k.arguments);
    } else if (name == "COMPCAD" || name == "COMPCURV" || name == "COMPOF" || name == "COMPON" || name == "FFWON" ||
               name == "FFWOF" || name == "TRAFOOF" || name == "UPATH" || name == "SPATH" ||
               name == "DYNNORM" || name == "DYNFINISH" || name == "DYNSEMIFIN" || name == "DYNROUGH") {
      // compressor, feed-forward, dynamic-response groups: no effect on this model
    } else {
      unknown(name);
    }
  }

  // CYCLE832(tolerance, machining type, …): the 840D high-speed setting. A tolerance selects G642 rounding
  // within it, SOFT and the compressor; no argument (or 0) deselects it (G64, BRISK).
  void cycle832(std::string_view arguments) {
    const auto comma = arguments.find(',');
    std::string_view first = arguments.substr(0, comma);
    while (!first.empty() && (first.front() == ' ')) first.remove_prefix(1);
    double value = 0.0;
    if (first.empty()) {
      pathMode = PathMode::Continuous;
      jerkLimited = 0;
      return;
    }
    const auto parsed =
        fast_float::from_chars(first.data(), first.data() + first.size(), value, fast_float::chars_format::fixed);
    if (parsed.ec != std::errc() || value < 0.0) return unknown("CYCLE832(" + std::string(first) + ")");
    if (value == 0.0) {
      pathMode = PathMode::Continuous;
      jerkLimited = 0;
      return;
    }
    roundingTolerance = value * unit;
    pathMode = PathMode::Rounding;
    tolerance = roundingTolerance;
    jerkLimited = 1;
  }

  void arc(Block& block, const double offset[3], const bool hasOffset[3], double radiusWord, bool hasRadius) {
    static constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};  // G17 XY/Z, G18 ZX/Y, G19 YZ/X
    const int* axes = kPlaneAxes[plane == 17 ? 0 : plane == 18 ? 1 : 2];
    const int u = axes[0], v = axes[1], n = axes[2];
    block.normal = Eigen::Vector3d::Unit(n);
    const Eigen::Vector3d& s = block.start;
    const Eigen::Vector3d& e = block.end;
    Eigen::Vector3d centre = s;
    if (hasRadius && !(hasOffset[u] || hasOffset[v])) {
      const double r = std::abs(radiusWord) * unit;
      const Eigen::Vector2d a(s[u], s[v]), b(e[u], e[v]);
      const Eigen::Vector2d chord = b - a;
      const double d = chord.norm();
      if (r <= 0.0 || d == 0.0)
        throw ParseError(lineNumber, "an arc by radius needs R > 0 and an end point away from the start");
      if (d > 2.0 * r * (1.0 + 1e-9) + 1e-9)
        throw ParseError(lineNumber, "arc radius " + std::to_string(r) + " mm is less than half the chord (" +
                                         std::to_string(d / 2) + " mm): no such arc");
      const double h = std::sqrt(std::max(0.0, r * r - d * d / 4.0));
      const Eigen::Vector2d left(-chord.y() / d, chord.x() / d);  // chord turned +90° about the normal
      // Counter-clockwise short arc: centre on the left of the chord; clockwise or R < 0 flips it.
      const bool clockwise = block.motion == Motion::ArcClockwise;
      const double side = (clockwise ? -1.0 : 1.0) * (radiusWord < 0 ? -1.0 : 1.0);
      const Eigen::Vector2d c = 0.5 * (a + b) + side * h * left;
      centre[u] = c.x();
      centre[v] = c.y();
    } else {
      if (!(hasOffset[u] || hasOffset[v]))
        throw ParseError(lineNumber, "arc without centre: give I/J/K (or R / CR=) for the active plane G" +
                                         std::to_string(plane));
      for (int a : {u, v}) centre[a] = arcCentreAbsolute ? offset[a] * unit : s[a] + offset[a] * unit;
    }
    centre[n] = s[n];
    const Eigen::Vector3d rs = s - centre, re = Eigen::Vector3d(e[u] - centre[u], e[v] - centre[v], 0.0);
    const double r0 = std::hypot(rs[u], rs[v]), r1 = re.head<2>().norm();
    if (r0 <= 1e-9) throw ParseError(lineNumber, "arc radius is zero: the centre is on the start point");
    if (std::abs(r1 - r0) > options.arcRadiusTolerance + 1e-3 * r0)
      throw ParseError(lineNumber, "arc end point is not on the circle: its radius is " + std::to_string(r1) +
                                       " mm, the start's " + std::to_string(r0) + " mm");
    double angle = std::atan2(rs[u] * re.y() - rs[v] * re.x(), rs[u] * re.x() + rs[v] * re.y());
    const bool full = std::hypot(e[u] - s[u], e[v] - s[v]) < 1e-9;
    if (block.motion == Motion::ArcCounterClockwise) {
      if (angle <= 0.0 || full) angle += 2.0 * M_PI;
    } else {
      if (angle >= 0.0 || full) angle -= 2.0 * M_PI;
    }
    if (full) angle = block.motion == Motion::ArcCounterClockwise ? 2.0 * M_PI : -2.0 * M_PI;
    block.center = centre;
    block.radius = r0;
    block.sweep = angle;
  }
};

GcodeReader::GcodeReader(std::istream& input, ReaderOptions options)
    : impl_(std::make_unique<Impl>(input, options)) {}
GcodeReader::~GcodeReader() = default;
bool GcodeReader::next(Block& block) { return impl_->next(block); }
const ReaderStats& GcodeReader::stats() const { return impl_->stats; }

std::vector<Block> readProgram(const std::string& text, const ReaderOptions& options) {
  std::istringstream stream(text);
  GcodeReader reader(stream, options);
  std::vector<Block> blocks;
  Block block;
  while (reader.next(block)) blocks.push_back(block);
  return blocks;
}

}  // namespace hsm::kinematics
