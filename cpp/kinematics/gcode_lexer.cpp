#include "kinematics/gcode_lexer.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace hsm::kinematics::detail {

namespace {
constexpr auto isLetter = isAsciiLetter;
constexpr auto isDigit = isAsciiDigit;
constexpr auto toUpper = asciiUpper;
}  // namespace

bool LineSource::next(std::string_view& line) {
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

std::string_view LineSource::trimmed(size_t from, size_t to) const {
  if (to > from && buffer_[to - 1] == '\r') --to;
  return std::string_view(buffer_.data() + from, to - from);
}

void LineSource::refill() {
  buffer_.erase(0, position_);
  position_ = 0;
  const size_t old = buffer_.size();
  buffer_.resize(old + kChunk);
  input_.read(buffer_.data() + old, kChunk);
  const auto got = static_cast<size_t>(input_.gcount());
  buffer_.resize(old + got);
  if (got == 0 || !input_) eof_ = true;
}

namespace {
bool has(std::string_view raw, std::string_view what) { return raw.find(what) != std::string_view::npos; }

}  // namespace

// A program in a language the reader does not take is refused at once, in one line that says what it is,
// instead of at its first odd word (or worse, read as something it is not).
void refuseOtherLanguages(std::string_view raw, long number) {
  const char* what = nullptr;
  if (has(raw, "BEGIN PGM")) {
    what = "a Heidenhain conversational (Klartext) program ('BEGIN PGM')";
  } else if ((has(raw, "G54 I") && !has(raw, "G54 I-")) || (has(raw, "G74 ") && has(raw, " L1") && !has(raw, "R")) ||
             has(raw, "A5=") || has(raw, "B5=")) {
    what = "a Heidenhain MillPlus program (G54 I.., G74 .. L1 home moves, G7 A5= B5= tilted planes)";
  } else if (has(raw, "G56 ") && has(raw, " H") && !has(raw, "G43")) {
    what = "an Okuma OSP program (G56 .. H: Okuma's tool length offset)";
  }
  if (what != nullptr)
    throw ParseError(number, std::string("this is ") + what + ": the simulator reads ISO G-code (LinuxCNC, grbl, "
                             "Fanuc, Haas) and Siemens 840D programs; post the part for one of them");
}

const char* afterComment(const char* p, const char* end, long line) {
  // Nested parentheses stay inside the comment: CAM posts write "(#508= (MILL_.25_PROFILE))".
  int depth = 0;
  for (; p < end; ++p) {
    if (*p == '(') ++depth;
    if (*p == ')' && --depth == 0) return p + 1;
  }
  throw ParseError(line, "comment '(' is not closed: add ')'");
}

void Line::parse(std::string_view raw, long number) {
  wordCount = 0;
  keywords.clear();
  // Words and keywords are read in capitals: a line that has lower-case letters is copied in capitals
  // first (CAM writes capitals: most lines are read where they are, without a copy).
  const char* p = raw.data();
  const char* end = p + raw.size();
  if (std::any_of(p, end, [](char c) { return c >= 'a' && c <= 'z'; })) {
    upper.assign(raw);
    for (char& c : upper) c = toUpper(c);
    p = upper.data();
    end = p + upper.size();
  }
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  if (p < end && *p == '/') ++p;  // block delete: the block runs (the switch is off)
  while (p < end) {
    const char c = *p;
    if (c == ' ' || c == '\t') {
      ++p;
    } else if (c == ';') {
      break;
    } else if (c == '(') {
      p = afterComment(p, end, number);
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

namespace {
// What a message quotes of the text at p: up to the next blank, at most 24 characters.
std::string quoted(const char* p, const char* end) {
  const char* token = p;
  while (token < end && token - p < 24 && *token != ' ' && *token != '\t') ++token;
  return std::string(p, token);
}

// Digits with at most one point, at p (no sign): the value, correctly rounded, and where it stops; nullptr
// when there are more than 15 significant digits (then fast_float reads it). A mantissa below 10^15 and a
// power of ten up to 10^22 are exact doubles, so one division rounds correctly (Clinger's fast path): the
// usual G-code number ("X12.3456") never reaches the general parser.
const char* smallDecimal(const char* p, const char* end, double& value) {
  static constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  auto digit = [](char c) { return static_cast<unsigned>(c - '0') < 10u; };
  while (p < end && *p == '0') ++p;  // leading zeros are not significant
  std::uint64_t mantissa = 0;
  const char* from = p;
  for (; p < end && digit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
  long digits = p - from, fraction = 0;
  if (p < end && *p == '.') {
    from = ++p;
    for (; p < end && digit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
    fraction = p - from;
    digits += fraction;
  }
  if (digits > 15 || fraction > 22) return nullptr;  // (the mantissa may have overflowed: not used)
  value = static_cast<double>(mantissa) / kPowers[fraction];
  return p;
}
}  // namespace

const char* Line::numberAt(const char* p, const char* end, double& value, std::string_view what, long number) {
  const bool negative = p < end && *p == '-';
  const char* digits = p < end && (*p == '+' || *p == '-') ? p + 1 : p;
  if (!(digits < end && (isDigit(*digits) || (*digits == '.' && digits + 1 < end && isDigit(digits[1])))))
    throw ParseError(number, "'" + std::string(what) + quoted(p, end) +
                                 "' is not a letter followed by a number (digits, an optional sign and point)");
  const char* stop = smallDecimal(digits, end, value);
  if (stop != nullptr) {
    if (negative) value = -value;
  } else {
    const auto parsed = fast_float::from_chars(*p == '+' ? p + 1 : p, end, value, fast_float::chars_format::fixed);
    if (parsed.ec != std::errc()) throw ParseError(number, "'" + std::string(what) + quoted(p, end) + "' is not a number");
    stop = parsed.ptr;
  }
  if (stop < end && (*stop == '.' || isDigit(*stop)))
    throw ParseError(number, "'" + std::string(what) + quoted(p, end) + "' is not a number");
  if (stop < end && (*stop == 'e' || *stop == 'E') && stop + 1 < end &&
      (isDigit(stop[1]) || ((stop[1] == '+' || stop[1] == '-') && stop + 2 < end && isDigit(stop[2]))))
    throw ParseError(number, "'" + std::string(what) + quoted(p, end) +
                                 "': G-code numbers have no exponent; write the number in full");
  if (!(std::abs(value) <= kMaxWordValue))
    throw ParseError(number, "'" + std::string(what) + std::string(p, std::min<size_t>(stop - p, 24)) +
                                 "' is out of range: words are at most " + std::to_string(long(kMaxWordValue)) +
                                 " in size");
  return stop;
}

const char* Line::word(const char* p, const char* end, long number) {
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

const char* Line::keyword(const char* p, const char* end, long number) {
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

const char* Line::assignment(const char* p, const char* end, Keyword& k, long number) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  const char* digits = p < end && (*p == '+' || *p == '-') ? p + 1 : p;
  const char* stop = p;
  if (digits < end && (isDigit(*digits) || *digits == '.')) {
    stop = numberAt(p, end, k.value, std::string(k.name) + "=", number);
    if (stop == end || *stop == ' ' || *stop == '\t' || *stop == ';') return stop;
  }
  // An expression or a variable (R1=R2*3): not evaluated; keep the name so it counts as unknown. A name in
  // quotes (T="DRILL 8.5") is one value, blanks and all.
  k.hasValue = false;
  if (p < end && *p == '"') {
    const char* close = std::find(p + 1, end, '"');
    return close < end ? close + 1 : end;
  }
  while (p < end && *p != ' ' && *p != '\t' && *p != ';') ++p;
  return p;
}

}  // namespace hsm::kinematics::detail
