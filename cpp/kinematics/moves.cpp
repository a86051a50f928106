#include "kinematics/moves.hpp"

#include <cmath>
#include <string>

namespace hsm::kinematics {

std::vector<Block> movesToBlocks(const MoveArray& moves, double feed, const Eigen::Vector3d& start) {
  if (!(feed > 0.0) || !std::isfinite(feed))
    throw InputError("feed " + std::to_string(feed) + " mm/s must be positive: give the cutting feed");
  std::vector<Block> blocks;
  blocks.reserve(static_cast<size_t>(moves.rows()));
  Eigen::Vector3d position = start;
  for (Eigen::Index i = 0; i < moves.rows(); ++i) {
    const Eigen::Vector3d target = moves.row(i).head<3>().transpose();
    if (!target.allFinite() || target.cwiseAbs().maxCoeff() > kMaxWordValue)
      throw InputError("move " + std::to_string(i + 1) + " has a coordinate that is not a number within ±" +
                       std::to_string(kMaxWordValue) + " mm: check the toolpath");
    if ((target - position).squaredNorm() == 0.0) continue;
    Block block;
    block.motion = moves(i, 3) != 0.0 ? Motion::Rapid : Motion::Linear;
    block.feed = block.motion == Motion::Rapid ? 0.0 : feed;
    block.start = position;
    block.end = target;
    block.line = static_cast<long>(i + 1);
    blocks.push_back(block);
    position = target;
  }
  return blocks;
}

}  // namespace hsm::kinematics
