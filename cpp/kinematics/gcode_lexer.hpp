// The lexical level of the G-code reader (internal): lines from a stream read in large chunks, and the
// words and keywords of one line. The modal interpreter (gcode_interpreter.hpp) works on what this gives.
#pragma once

#include "kinematics/gcode.hpp"

#include <array>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail {

// Lines from a stream, read in large chunks.
class LineSource {
public:
  explicit LineSource(std::istream& input) : input_(input) { buffer_.reserve(kChunk * 2); }

  // The next line without its end-of-line characters; false at the end. A line longer than
  // kMaxLineLength is refused as soon as that many characters have come without a line end.
  bool next(std::string_view& line);

private:
  static constexpr size_t kChunk = 1 << 20;

  std::string_view trimmed(size_t from, size_t to) const;

  void refill();

  std::istream& input_;
  std::string buffer_;
  size_t position_ = 0;
  long lines_ = 0;
  bool eof_ = false;
};

inline constexpr long kDialectLines = 40;  // a program in another language says so in its first lines

// A line of a program in a language the reader does not take (Heidenhain conversational, MillPlus, Okuma OSP):
// a ParseError that says what it is, at once, instead of at its first odd word (or worse, read as something
// it is not). Given the first kDialectLines lines.
void refuseOtherLanguages(std::string_view raw, long number);

// Past the comment that opens at p ('('), up to the ')' that closes it (nested ones included); ParseError
// naming `line` when it is not closed.
const char* afterComment(const char* p, const char* end, long line);

// ---------------------------------------------------------------------------------------------------------
// Words of one line

struct Word {
  char letter;
  double value;
  std::string_view text;  // as written, for messages
};

struct Keyword {
  std::string_view name;       // into the line as read, or into Line::upper
  std::string_view arguments;  // inside ( ), for calls
  bool hasValue = false;       // NAME=value
  double value = 0.0;
  bool call = false;
};

class Line {
public:
  std::array<Word, 64> words{};
  int wordCount = 0;
  std::vector<Keyword> keywords;
  std::string upper;  // the line in capitals, when it had lower-case letters: words then point into it

  // Splits `raw` into words and keywords; throws ParseError on malformed text.
  void parse(std::string_view raw, long number);

private:
  // A G-code number at p: an optional sign, digits with at most one point, no exponent, nan or inf, at
  // most kMaxWordValue. Returns the end of the number; `what` names the word in messages.
  const char* numberAt(const char* p, const char* end, double& value, std::string_view what, long number);

  const char* word(const char* p, const char* end, long number);

  const char* keyword(const char* p, const char* end, long number);

  const char* assignment(const char* p, const char* end, Keyword& k, long number);
};

}  // namespace hsm::kinematics::detail
