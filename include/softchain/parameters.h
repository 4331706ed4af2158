#pragma once
// The FEM tier's run-time parameters: one struct per .prm subsection (the
// layout of deal.II's step-44). The subsections owned by the deal.II-free
// tiers (Finger design, Reduction, Chain) are read by those tiers.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <vector>

namespace softchain
{
  using namespace dealii;

  // subsection Design
  struct DesignParameters
  {
    std::string name;
    std::string output_directory; // default output/<name>
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  // subsection Mesh
  struct MeshParameters
  {
    std::string  source;       // "built-in bender" | "file" | "finger design"
    std::string  mesh_file;    // gmsh .msh (source = file)
    std::string  spring_file;  // spring polylines (optional)
    std::string  element_type; // Q1 | Q2 | P1 | P2
    unsigned int global_refinements = 0;
    double       node_jitter        = 0; // fraction of the shortest edge (stress test)
    // The built-in hollow bender (length, width, height, wall, cells per mm).
    double       bender_length = 0.08, bender_width = 0.018,
           bender_height = 0.012, bender_wall = 0.002;
    unsigned int bender_cells_length = 20;
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  struct MaterialRegion
  {
    double youngs_modulus;
    double poissons_ratio;
  };

  // subsection Materials (one nested subsection per gmsh volume name)
  struct MaterialParameters
  {
    std::string                           strain_energy; // "log" | "split"
    std::map<std::string, MaterialRegion> regions;
    double                                density = 1070.0; // kg/m^3
    static void declare(ParameterHandler                &prm,
                        const std::vector<std::string> &region_names);
    void        parse(ParameterHandler                &prm,
                      const std::vector<std::string> &region_names);
  };

  // subsection Springs
  struct SpringParameters
  {
    // Axial rigidity EA [N] of each named network (tension T = EA * strain).
    std::map<std::string, double> axial_rigidity;
    bool                          generate_for_bender = true;
    double                        thread_pitch        = 0.004; // m
    double                        smoothing_strain    = 1e-3;  // d of the tension law
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  struct PointLoad
  {
    Point<3>     point; // reference position, inside the body
    Tensor<1, 3> force; // N, fixed in world axes (dead load)
  };

  // subsection Loads
  struct LoadParameters
  {
    double                 pressure = 0.0; // Pa, follower load on `cavity`
    std::vector<PointLoad> point_loads;
    Tensor<1, 3>           tip_traction; // N/m^2, dead load on `tip`
    bool                   gravity = false;
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  // subsection Solver
  struct SolverParameters
  {
    double       residual_tolerance;   // relative to the external load norm
    double       displacement_tolerance; // relative Newton update
    unsigned int max_newton_iterations;
    double       initial_load_step;
    double       min_load_step;
    double       max_load_step;
    std::string  linear_solver; // auto | direct | iterative
    unsigned int direct_solver_max_dofs;
    std::string  direct_solver_package;
    double       krylov_tolerance;
    bool         line_search;
    bool         secant_predictor;
    unsigned int threads;
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  // subsection Output
  struct OutputParameters
  {
    bool         write_vtu;
    bool         write_load_steps;
    unsigned int subdivisions; // for high-order output; 0: element degree
    bool         verbose;
    static void declare(ParameterHandler &prm);
    void        parse(ParameterHandler &prm);
  };

  // All FEM-tier parameters of one .prm file.
  struct Parameters
  {
    std::string        file;
    DesignParameters   design;
    MeshParameters     mesh;
    MaterialParameters materials;
    SpringParameters   springs;
    LoadParameters     loads;
    SolverParameters   solver;
    OutputParameters   output;

    // Reads `file`. Throws data::InputError naming file, line and parameter
    // for anything unknown, malformed or out of range.
    static Parameters read(const std::string &file);
  };

  // The top-level subsections that other tiers own and that the FEM tier's
  // ParameterHandler therefore skips.
  const std::vector<std::string> &subsections_of_other_tiers();
} // namespace softchain
