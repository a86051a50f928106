#include "kinematics/kept_lines.hpp"

#include "kinematics/gcode.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>

namespace hsm::kinematics::detail {

void KeptFile::keep(std::string_view raw, long number) {
  if (chunks.empty() || chunkUsed + raw.size() > kChunkBytes) {
    if (!spare.empty() && raw.size() <= kChunkBytes) {
      chunks.push_back(std::move(spare.back()));
      spare.pop_back();
    } else {
      chunks.push_back(std::make_unique<char[]>(std::max(kChunkBytes, raw.size())));
    }
    chunkUsed = 0;
  }
  char* at = chunks.back().get() + chunkUsed;
  std::memcpy(at, raw.data(), raw.size());
  chunkUsed += raw.size();
  lines.push_back(KeptLine{std::string_view(at, raw.size()), number,
                           static_cast<std::uint32_t>(chunksDropped + chunks.size() - 1), -1});
}

void KeptFile::dropFront(size_t count) {
  lines.erase(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(count));
  dropped += count;
  while (!lines.empty() && chunksDropped < lines.front().chunk) {
    if (spare.size() < 4) spare.push_back(std::move(chunks.front()));  // (a longer line's chunk is as good)
    chunks.pop_front();
    ++chunksDropped;
  }
}

KeptFiles::KeptFiles(LineSource& source) : source_(source) {
  files_.emplace_back();
  files_.back().name = "the program";
  files_.back().streaming = true;
}

KeptLine* KeptFiles::readOn(KeptFile& file, size_t offset) {
  while (offset >= file.lines.size()) {
    if (!file.streaming) return nullptr;
    std::string_view raw;
    if (!source_.next(raw)) return nullptr;
    file.keep(raw, ++streamed_);
  }
  return &file.lines[offset];
}

void KeptFiles::letGoBehind(const LineCursor& running) {
  KeptFile& program = files_[0];
  if (running.file != 0 || running.index < program.dropped + 2 * kKeptBehind) return;
  program.dropFront(std::min(running.index - program.dropped - kKeptBehind, program.lines.size()));
}

long KeptFiles::load(const std::string& path, const std::string& name, long line) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) return -1;
  files_.emplace_back();
  KeptFile& file = files_.back();
  file.name = name;
  LineSource lines(stream);
  std::string_view raw;
  for (long n = 1; lines.next(raw); ++n) {
    if (file.lines.size() >= kMaxKeptLines)
      throw ParseError(line, path + " is over " + std::to_string(kMaxKeptLines) + " lines");
    file.keep(raw, n);
  }
  return static_cast<long>(files_.size() - 1);
}

}  // namespace hsm::kinematics::detail
