// Points as the core hands them around: an (N, 3) array, row-major so that it maps one to one onto a numpy array.
#pragma once

#include <Eigen/Geometry>  // points come with cross products and boxes

namespace hsm::geometry {

using PointArray = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

}  // namespace hsm::geometry
