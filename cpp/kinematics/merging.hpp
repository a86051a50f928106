// Short G1 blocks merged before planning, as the controllers do it: what CAM writes for high-speed
// machining (chains of chords of a few hundredths of a millimetre) is not what the machine executes.
//
// LinuxCNC 2.9 (emccanon.cc, its "naive CAM detector"): in G64 P… [Q…] (Q defaults to P; G64 alone and
// G61 merge nothing), consecutive G1 moves at one feed are joined into one line from the chain's start to
// its last point while every point of the chain lies within Q of that line; a chain holds at most 100
// points. A merged line runs as one block: one junction, one block-processing limit.
//
// Siemens 840D compressor (COMPCAD, COMPCURV, COMPSURF; CYCLE832 with a tolerance switches it on):
// consecutive G1 blocks shorter than the machine's compressor_path_limit (MD20170
// COMPRESS_BLOCK_PATH_LIMIT) are fitted by polynomials within the tolerance. The path keeps its shape (the
// planner still sees the curvature of the chords), but the block-processing limit counts compressed blocks,
// not program blocks: we group the chords up to compressor_path_limit of path and give each block of a
// group the group's length for that limit (rateLength). Our reading of Siemens's documentation, not
// measured on a machine.
#pragma once

#include "kinematics/gcode.hpp"
#include "kinematics/machine.hpp"

#include <functional>
#include <vector>

namespace hsm::kinematics {

inline constexpr size_t kLinuxCncMaxChain = 100;  // points a naive-CAM chain holds (emccanon.cc)

class BlockMerger {
public:
  // Blocks come out through `out`, in order, merged as `machine`'s controller merges them.
  BlockMerger(const MachineModel& machine, std::function<void(const Block&)> out);

  void add(const Block& block);
  // Emits what is still held (the end of the program).
  void finish();

private:
  bool linuxCncLinkable(const Block& block) const;
  void flush();

  const MachineModel& machine_;
  std::function<void(const Block&)> out_;
  std::vector<Block> held_;  // the chain (LinuxCNC) or group (840D) being built
  double heldLength_ = 0.0;
};

}  // namespace hsm::kinematics
