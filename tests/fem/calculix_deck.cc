#include "calculix_deck.h"

#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/hyperelastic_material.h>

#include <deal.II/grid/grid_tools.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace softchain::fem::test
{
  using namespace dealii;

  namespace
  {
    // deal.II's lexicographic vertex order to Abaqus' counter-clockwise one.
    constexpr unsigned int corner[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    // C3D20R mid-side nodes 9-20 as the deal.II vertex pairs of their edges:
    // the bottom face's edges, the top face's, then the vertical ones.
    constexpr unsigned int edge[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                          {7, 6}, {6, 4}, {0, 4}, {1, 5}, {3, 7}, {2, 6}};
    // deal.II face f of a hexahedron is CalculiX face P<face[f]>.
    constexpr unsigned int ccx_face[6] = {6, 4, 3, 5, 1, 2};

    // Node numbers: mesh vertex v is node v + 1; with C3D20R the midpoint
    // of the edge between vertices (a, b), a < b, is numbered after them.
    class NodeNumbers
    {
    public:
      explicit NodeNumbers(const Triangulation<3> &mesh)
        : next(mesh.n_vertices() + 1)
      {}
      unsigned int vertex(const unsigned int v) const { return v + 1; }
      // A node of no mesh vertex or edge (the rigid plane's).
      unsigned int extra() { return next++; }
      unsigned int midpoint(unsigned int a, unsigned int b)
      {
        if (a > b)
          std::swap(a, b);
        const auto [it, inserted] = midpoints.try_emplace({a, b}, next);
        next += inserted;
        return it->second;
      }
      const std::map<std::pair<unsigned int, unsigned int>, unsigned int> &all_midpoints() const
      {
        return midpoints;
      }

    private:
      unsigned int                                                  next;
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> midpoints;
    };

    void write_point(std::ostream &inp, const unsigned int node, const Point<3> &x)
    {
      inp << node << ", " << x[0] << ", " << x[1] << ", " << x[2] << '\n';
    }

    void write_node_set(std::ostream &inp, const std::string &name,
                        const std::set<unsigned int> &nodes)
    {
      inp << "*NSET, NSET=" << name << '\n';
      for (const unsigned int n : nodes)
        inp << n << ",\n";
    }

    // The rigid plane y = plane.y as the top face (S5) of one C3D8 slab
    // below it, reaching half the body's size beyond the body along x and z
    // (its nodes: the set PLANE, fixed by the caller), and the contact of
    // the cells' -y faces (deal.II face 2, S3) with that face.
    void write_rigid_plane(std::ostream &inp, const Triangulation<3> &mesh, NodeNumbers &numbers,
                           const CalculixDeck::RigidPlane &plane, const double youngs_modulus)
    {
      const auto   box = GridTools::compute_bounding_box(mesh);
      const auto   lo = box.get_boundary_points().first, hi = box.get_boundary_points().second;
      const auto   size = hi - lo;
      const double x[2] = {lo[0] - size[0] / 2, hi[0] + size[0] / 2},
                   y[2] = {plane.y - size[1], plane.y}, z[2] = {lo[2] - size[2] / 2, hi[2] + size[2] / 2};
      unsigned int slab[8]; // deal.II's lexicographic order
      inp << "*NODE, NSET=PLANE\n";
      for (unsigned int v = 0; v < 8; ++v)
        write_point(inp, slab[v] = numbers.extra(), Point<3>(x[v & 1], y[(v >> 1) & 1], z[v >> 2]));
      const unsigned int element = mesh.n_active_cells() + 1;
      inp << "*ELEMENT, TYPE=C3D8, ELSET=RIGID\n" << element;
      for (const unsigned int v : corner)
        inp << ", " << slab[v];
      inp << "\n*SOLID SECTION, ELSET=RIGID, MATERIAL=SILICONE\n" // any: its nodes are fixed
          << "*SURFACE, NAME=TABLE\n" << element << ", S" << ccx_face[3] << '\n'
          << "*SURFACE, NAME=BODY\n";
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->face(2)->at_boundary() && cell->face(2)->boundary_id() != boundary::base)
          inp << cell->active_cell_index() + 1 << ", S" << ccx_face[2] << '\n';
      // Slave BODY, master TABLE; the interaction's law: p = K overclosure,
      // quasi-bilinear for node to surface, which needs the tension
      // sigma_inf it tends to at large clearances: 1e-8 E, negligible.
      inp << "*CONTACT PAIR, INTERACTION=TABLE_CONTACT, TYPE="
          << (plane.surface_to_surface ? "SURFACE TO SURFACE" : "NODE TO SURFACE") << "\nBODY, TABLE\n"
          << "*SURFACE INTERACTION, NAME=TABLE_CONTACT\n"
          << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n" << plane.penalty << ", "
          << 1e-8 * youngs_modulus << '\n';
      if (plane.friction > 0) // mu, stick slope
        inp << "*FRICTION\n" << plane.friction << ", " << plane.stick_slope << '\n';
    }

    // Per node of the tip faces, the consistent nodal load of a unit
    // uniform traction: integral of N_a dA over each parallelogram face.
    std::map<unsigned int, double> tip_node_areas(const Triangulation<3> &mesh, NodeNumbers &numbers,
                                                  const bool quadratic)
    {
      if (!quadratic)
        {
          std::map<unsigned int, double> area;
          for (const auto &[v, share] : tip_area_shares(mesh))
            area[numbers.vertex(v)] = share;
          return area;
        }
      std::map<unsigned int, double> area;
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary::tip)
          {
            for (unsigned int v = 0; v < 4; ++v)
              area[numbers.vertex(face->vertex_index(v))] -= face->measure() / 12;
            for (unsigned int l = 0; l < 4; ++l)
              area[numbers.midpoint(face->line(l)->vertex_index(0), face->line(l)->vertex_index(1))] +=
                face->measure() / 3;
          }
      return area;
    }
  } // namespace

  std::map<unsigned int, double> tip_area_shares(const Triangulation<3> &mesh)
  {
    std::map<unsigned int, double> share;
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == boundary::tip)
        for (unsigned int v = 0; v < 4; ++v)
          share[face->vertex_index(v)] += face->measure() / 4;
    return share;
  }

  void CalculixDeck::write(const std::string &file, const Triangulation<3> &mesh, const Load &load,
                           const std::vector<unsigned int> &printed) const
  {
    const ElasticConstants c(youngs_modulus, poissons_ratio);
    const bool             quadratic = element == Element::C3D20R;
    NodeNumbers            numbers(mesh);
    std::ostringstream     elements; // written after the nodes it numbers
    elements.precision(12);
    elements << "*ELEMENT, TYPE=" << (quadratic ? "C3D20R" : "C3D8") << ", ELSET=EALL\n";
    std::set<unsigned int> base;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        elements << cell->active_cell_index() + 1;
        for (const unsigned int v : corner)
          elements << ", " << numbers.vertex(cell->vertex_index(v));
        if (quadratic) // CalculiX continues a long element line on the next
          for (unsigned int e = 0; e < 12; ++e)
            elements << (e == 7 ? ",\n" : ", ")
                     << numbers.midpoint(cell->vertex_index(edge[e][0]), cell->vertex_index(edge[e][1]));
        elements << '\n';
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary::base)
            for (unsigned int v = 0; v < 4; ++v)
              {
                base.insert(numbers.vertex(cell->face(f)->vertex_index(v)));
                for (unsigned int w = v + 1; w < 4 && quadratic; ++w)
                  if ((v ^ w) == 1 || (v ^ w) == 2) // the face's four edges
                    base.insert(numbers.midpoint(cell->face(f)->vertex_index(v),
                                                 cell->face(f)->vertex_index(w)));
              }
      }

    std::ofstream inp(file);
    inp.precision(12); // CalculiX reads fields of at most 20 characters
    inp << "*NODE, NSET=NALL\n";
    const auto &x = mesh.get_vertices();
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      write_point(inp, numbers.vertex(v), x[v]);
    for (const auto &[ends, node] : numbers.all_midpoints()) // straight edges
      write_point(inp, node, (x[ends.first] + x[ends.second]) / 2);
    inp << elements.str();
    write_node_set(inp, "BASE", base);
    std::set<unsigned int> print;
    for (const unsigned int v : printed)
      print.insert(numbers.vertex(v));
    write_node_set(inp, "PRINTED", print);
    inp << "*MATERIAL, NAME=SILICONE\n*HYPERELASTIC, NEO HOOKE\n"
        << c.mu / 2 << ", " << 2 / c.kappa << '\n'
        << "*SOLID SECTION, ELSET=EALL, MATERIAL=SILICONE\n";
    if (plane)
      write_rigid_plane(inp, mesh, numbers, *plane, youngs_modulus);
    inp << "*BOUNDARY\nBASE, 1, 3\n" << (plane ? "PLANE, 1, 3\n" : "")
        << "*STEP, NLGEOM, INC=1000\n*STATIC\n"
        << first_increment << ", 1.0, 1e-5, " << max_increment << '\n'
        << "*CONTROLS, PARAMETERS=FIELD\n" << tolerance << ", " << tolerance << '\n';
    if (load.tip_traction_y != 0 || load.tip_traction_z != 0)
      {
        inp << "*CLOAD\n";
        for (const auto &[node, a] : tip_node_areas(mesh, numbers, quadratic))
          for (const auto &[direction, t] : {std::pair{2, load.tip_traction_y}, std::pair{3, load.tip_traction_z}})
            if (t != 0)
              inp << node << ", " << direction << ", " << t * a << '\n';
      }
    if (load.pressure != 0)
      {
        inp << "*DLOAD\n";
        for (const auto &cell : mesh.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary::cavity)
              inp << cell->active_cell_index() + 1 << ", P" << ccx_face[f] << ", " << load.pressure
                  << '\n';
      }
    inp << "*NODE PRINT, NSET=PRINTED\nU\n";
    if (plane) // the sum of the plane's reactions: -(the force it receives)
      inp << "*NODE PRINT, NSET=PLANE, TOTALS=ONLY\nRF\n";
    inp << "*END STEP\n";
  }

  std::map<unsigned int, Tensor<1, 3>> calculix_displacements(const std::string &dat)
  {
    std::ifstream                        in(dat);
    std::string                          line;
    std::map<unsigned int, Tensor<1, 3>> u;
    bool                                 displacements = false; // in such a block
    while (std::getline(in, line))
      {
        if (line.find(" for set ") != std::string::npos) // a block's title
          displacements = line.find("displacements") != std::string::npos;
        std::istringstream words(line);
        unsigned int       node;
        Tensor<1, 3>       value;
        if (displacements && words >> node >> value[0] >> value[1] >> value[2])
          u[node - 1] = value;
      }
    return u;
  }

  Tensor<1, 3> calculix_mean_tip_displacement(const std::string &dat, const Triangulation<3> &mesh)
  {
    const auto   u = calculix_displacements(dat);
    Tensor<1, 3> sum;
    double       area = 0;
    for (const auto &[v, a] : tip_area_shares(mesh))
      {
        if (u.count(v) == 0)
          throw std::runtime_error(dat + " has no displacement of tip vertex " + std::to_string(v));
        sum += a * u.at(v);
        area += a;
      }
    return sum / area;
  }

  Tensor<1, 3> calculix_total_force(const std::string &dat, const std::string &set)
  {
    std::ifstream in(dat);
    std::string   line;
    Tensor<1, 3>  force;
    bool          found = false, after_title = false;
    while (std::getline(in, line))
      {
        if (line.find("total force (fx,fy,fz) for set " + set + " ") != std::string::npos)
          after_title = true;
        else if (std::istringstream words(line); after_title && words >> force[0] >> force[1] >> force[2])
          after_title = false, found = true;
      }
    if (!found)
      throw std::runtime_error(dat + " has no total force of the set " + set);
    return force;
  }
} // namespace softchain::fem::test
