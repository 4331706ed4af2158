#include <softchain/chain/base_wrench.h>

namespace softchain::chain
{
  Wrench base_wrench(const KinematicChain &chain, const ChainPose &pose, const ChainLoad &load,
                     const Eigen::Vector3d &moment_point)
  {
    Wrench wrench;
    for (const PointLoad &p : load.point_loads)
      {
        const int             link = chain.link_of(p.reference_point);
        const Eigen::Vector3d x    = chain.point_position(pose, link, p.reference_point);
        wrench.force += p.force;
        wrench.moment += (x - moment_point).cross(p.force);
      }
    return wrench;
  }
} // namespace softchain::chain
