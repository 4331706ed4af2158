#pragma once
// The CollisionSurface of a finger from its FEM database: the outer surface
// of the database mesh (boundary faces of its cells that are not cavity
// faces; vertices of the clamped base left out), carried by the links of a
// ChainModel.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/chain_model.h>
#include <softchain/chain/collision_surface.h>
#include <softchain/data/actuation_database.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace softchain::chain
{
  // The vertices of `mesh`'s outer surface: those of the faces that belong to
  // one cell only, without the faces whose vertices are all cavity vertices,
  // and without the clamped base's vertices. Sorted node indices.
  std::vector<std::int64_t> outer_surface_nodes(const data::MeshRecord &mesh);

  // The cavity's extent along x in the reference mesh (its triangles' nodes):
  // between these the palm is a plate over the cavity, which gives under
  // contact; the solid base fill and tip cap lie outside.
  std::pair<double, double> cavity_span(const data::MeshRecord &mesh);

  // The outer surface carried rigidly by the links of `model`'s reference
  // chain: one row, at p = 0 (the paper's rigid links, the baseline). Its
  // points: the outer faces' vertices (`subdivisions` = 1) or a grid of
  // subdivisions x subdivisions intervals on each face, bilinear in its
  // vertices (barycentric on a triangle), so that a point follows the
  // deformed mesh; each point once, none carried only by clamped vertices.
  CollisionSurface rigid_collision_surface(const ChainModel &model, const data::MeshRecord &mesh,
                                           int subdivisions = 1);

  // The deformed nodes of the converged pressure-only samples (role
  // "pressure", no forces, tip motion, obstacles or volume control), by
  // pressure.
  using InflatedNodes = std::map<double, std::vector<data::Point3>>;

  // What the collision surfaces need from a database, in one pass over its
  // samples: whether any is a contact sample, and the inflated nodes.
  struct SurfaceSamples
  {
    bool          contact = false;
    InflatedNodes inflated;

    static SurfaceSamples read(const data::ActuationDatabase &database);
  };

  // The same surface shaped by the pressure: one row per pressure of
  // `inflated`, the offsets from the chain's own equilibrium pose at that
  // pressure (CollisionSurface). A pressure whose chain equilibrium fails
  // is left out.
  CollisionSurface pressure_shaped_collision_surface(const ChainModel &model, const data::MeshRecord &mesh,
                                                     const InflatedNodes       &inflated,
                                                     const EquilibriumSettings &settings, int subdivisions = 1);
} // namespace softchain::chain
