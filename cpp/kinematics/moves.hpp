// A toolpath handed to the simulator as it is, without writing and re-reading G-code text.
#pragma once

#include "kinematics/gcode.hpp"

#include <Eigen/Core>

#include <vector>

namespace hsm::kinematics {

// Rows of x, y, z (mm) and a rapid flag (≠ 0: G0), row-major to map one to one onto a numpy array: the
// moves of the toolpath generators.
using MoveArray = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

// The blocks a G-code reader would make of the moves written as G0/G1 lines in continuous path mode:
// each row moves from the previous point (the first from `start`), a G1 at `feed` mm/s; moves to where
// the tool already is are skipped, as the reader skips them; block lines count the rows from 1.
// InputError for a feed that is not positive or a coordinate that is not a finite number within
// kMaxWordValue.
std::vector<Block> movesToBlocks(const MoveArray& moves, double feed,
                                 const Eigen::Vector3d& start = Eigen::Vector3d::Zero());

}  // namespace hsm::kinematics
