#pragma once
// The database's std::array points as Eigen vectors.
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

namespace softchain::data
{
  inline Eigen::Vector3d vector_of(const data::Point3 &p)
  {
    return Eigen::Vector3d(p[0], p[1], p[2]);
  }
} // namespace softchain::data
