#include "kinematics/merging.hpp"

#include <algorithm>
#include <limits>

namespace hsm::kinematics {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool sameMotion(const Block& a, const Block& b) {
  return a.motion == Motion::Linear && b.motion == Motion::Linear && a.feed == b.feed && a.pathMode == b.pathMode &&
         a.tolerance == b.tolerance && a.mergeTolerance == b.mergeTolerance && a.compressor == b.compressor &&
         a.jerkLimited == b.jerkLimited;
}

// Distance from p to the segment [a, b].
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d m = b - a;
  const double mm = m.squaredNorm();
  const double t = mm > 0.0 ? std::clamp(m.dot(p - a) / mm, 0.0, 1.0) : 0.0;
  return (p - (a + t * m)).norm();
}
}  // namespace

BlockMerger::BlockMerger(const MachineModel& machine, std::function<void(const Block&)> out)
    : machine_(machine), out_(std::move(out)) {}

bool BlockMerger::linuxCncLinkable(const Block& block) const {
  if (held_.size() > kLinuxCncMaxChain || !sameMotion(held_.front(), block)) return false;
  const Eigen::Vector3d& start = held_.front().start;
  if (block.end == start) return false;
  for (const Block& b : held_)
    if (distanceToSegment(b.end, start, block.end) > block.mergeTolerance) return false;
  return true;
}

void BlockMerger::add(const Block& block) {
  if (block.rotary) {  // 5-axis blocks are not merged: the rotary axes' moves would be lost (not modelled)
    flush();
    return out_(block);
  }
  const bool linuxcnc = machine_.controller == ControllerKind::LinuxCNC;
  if (linuxcnc) {
    const bool mergeable = block.motion == Motion::Linear && block.mergeTolerance > 0.0;
    if (!held_.empty() && !(mergeable && linuxCncLinkable(block))) flush();
    if (!mergeable) return out_(block);
    held_.push_back(block);
    return;
  }
  if (machine_.controller != ControllerKind::Siemens840D) return out_(block);
  const double length = block.motion == Motion::Linear && block.compressor ? block.length() : kInfinity;
  const bool compressible = length <= machine_.compressorPathLimit;
  const bool fits = compressible && (held_.empty() || (sameMotion(held_.front(), block) &&
                                                       heldLength_ + length <= machine_.compressorPathLimit));
  if (!fits) flush();
  if (!compressible) return out_(block);
  held_.push_back(block);
  heldLength_ += length;
}

void BlockMerger::flush() {
  if (held_.empty()) return;
  if (machine_.controller == ControllerKind::LinuxCNC) {
    Block merged = held_.back();  // its feed, modes and line number; from the chain's start
    merged.start = held_.front().start;
    out_(merged);
  } else {
    for (Block& b : held_) {
      b.rateLength = heldLength_;
      out_(b);
    }
  }
  held_.clear();
  heldLength_ = 0.0;
}

void BlockMerger::finish() { flush(); }

}  // namespace hsm::kinematics
