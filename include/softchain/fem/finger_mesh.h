#pragma once
// FingerMesh: the serial reference mesh of a design with its boundary ids
// (boundary_ids.h), material regions, spring polylines and fibre sheets, from one of three
// sources: the built-in hollow bender, a gmsh .msh file, or a parametric
// finger design meshed by gmsh (source/geometry).
#include <softchain/fem/fibre_sheet.h>
#include <softchain/fem/parameters.h>
#include <softchain/fem/spring_polyline.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  struct FingerMesh
  {
    dealii::Triangulation<3>            triangulation;
    std::vector<std::string>    material_names; // by material id
    std::vector<SpringPolyline> springs;
    std::vector<FibreSheet>     sheets;
    std::string                 description; // for logs and the database

    // Throws data::InputError naming the file or parameter on bad input
    // (e.g. a spring network without its Springs/Axial rigidity).
    static void build(const Parameters &prm, FingerMesh &mesh);

  private:
    static void check_spring_rigidities(const Parameters &prm, const FingerMesh &mesh);
  };

  // Reads an ASCII gmsh file and maps its physical names (base, cavity, tip,
  // material volumes) to SoftChain's boundary and material ids.
  void read_gmsh_mesh(const std::string &file, FingerMesh &mesh);
} // namespace softchain::fem
