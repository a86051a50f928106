// The lines of a program and of its subprogram files, kept so that jumps, loops and calls can go back to them
// (internal, shared by the Fanuc/Haas and the 840D program flows). The program itself is read from its source as
// its lines are needed; a subprogram file is read whole when it is first called. Text is kept in chunks of
// kChunkBytes (no allocation per line, chunks let go are used again); the program keeps kKeptBehind lines behind
// the one running when nothing (a loop, a call) holds them: a jump back further is refused, naming the limit (a
// program that long is drip-fed, and a control cannot jump back in it either).
#pragma once

#include "kinematics/gcode_lexer.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail {

inline constexpr size_t kMaxKeptLines = 2'000'000;  // lines of a subprogram file, lines searched for a label
inline constexpr size_t kKeptBehind = 1 << 15;       // the program's lines kept behind the one running
inline constexpr size_t kChunkBytes = 1 << 20;

struct KeptLine {
  std::string_view text;  // into its file's arena
  long number;            // its line number in its file
  std::uint32_t chunk;    // the arena chunk holding it, counted from the file's first
  std::int32_t compiled;  // the line compiled by the program flow that runs it (its index there), −1 not yet
};

struct KeptFile {
  std::string name;
  std::deque<KeptLine> lines;
  size_t dropped = 0;      // lines let go from the front (the program only)
  bool streaming = false;  // the program itself: read from the source as needed
  std::deque<std::unique_ptr<char[]>> chunks;
  std::vector<std::unique_ptr<char[]>> spare;  // chunks let go, to be used again
  size_t chunkUsed = 0, chunksDropped = 0;

  void keep(std::string_view raw, long number);
  void dropFront(size_t count);
};

struct LineCursor {
  size_t file = 0, index = 0;  // index counts from the file's first line, dropped ones included
  bool operator==(const LineCursor& o) const { return file == o.file && index == o.index; }
  bool operator!=(const LineCursor& o) const { return !(*this == o); }
};

class KeptFiles {
public:
  // File 0 is the program, read from `source` as needed.
  explicit KeptFiles(LineSource& source);
  // The line at `at`; null past the file's end or for a line let go.
  KeptLine* fetch(const LineCursor& at) {
    KeptFile& file = files_[at.file];
    if (at.index < file.dropped) return nullptr;
    const size_t offset = at.index - file.dropped;
    return offset < file.lines.size() ? &file.lines[offset] : readOn(file, offset);
  }
  // The program's next line from the source, when every line read so far has been let go or passed: then the
  // caller keeps it (keep) or passes it (pass: it is let go at once, nothing can come back to it).
  bool readNext(std::string_view& raw, long& number) {
    if (!source_.next(raw)) return false;
    number = ++streamed_;
    return true;
  }
  void keep(std::string_view raw, long number) { files_[0].keep(raw, number); }
  void pass() { ++files_[0].dropped; }
  // Lets the program's lines go that are more than kKeptBehind behind `running` (a line of the program).
  void letGoBehind(const LineCursor& running);
  // Reads the file at `path` whole as a new file named `name`; its index, or −1 when it cannot be opened.
  // Throws ParseError (at `line`) for a file of over kMaxKeptLines lines.
  long load(const std::string& path, const std::string& name, long line);
  KeptFile& operator[](size_t file) { return files_[file]; }
  const KeptFile& operator[](size_t file) const { return files_[file]; }
  size_t size() const { return files_.size(); }

private:
  KeptLine* readOn(KeptFile& file, size_t offset);  // the program's lines read from the source up to `offset`

  LineSource& source_;
  std::deque<KeptFile> files_;  // a deque: a file (its arena) never moves
  long streamed_ = 0;
};

}  // namespace hsm::kinematics::detail
