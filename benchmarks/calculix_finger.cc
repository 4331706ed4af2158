// A design's mesh-converged answer without its reinforcement, checked by an
// independent code: SoftChain (Q2, 27-node Lagrange hexahedra, 3x3x3 Gauss
// points) and CalculiX (C3D20R, 20-node serendipity hexahedra, 2x2x2 points)
// solve the same finger on the same meshes, refined along the finger and
// across the walls, under a follower pressure on the cavity or a dead tip
// force (a uniform traction on the tip face) that bends it. The springs
// are switched off (EA = 0: CalculiX has no embedded tension-only
// springs), and both codes use the same neo-Hookean energy (SoftChain's
// `split`, CalculiX's NEO HOOKE to O((J - 1)^3); tests/fem/calculix_deck.h).
//
// Per mesh: each code's area-weighted mean displacement of the tip face and
// its wall time; then, per scene and code, a Richardson estimate of the converged
// mean tip displacement from its three finest meshes (Celik et al. 2008,
// J. Fluids Eng. 130, 078001: observed order by fixed-point iteration for
// unequal refinement ratios, h = DoFs^(-1/3)), component by component where
// the three converge in order. The two elements converge from different
// discretisations, so agreement of the two estimates checks the converged
// answer of the solid; docs/fem_accuracy.md has the table for P10.
//
// Run: calculix_finger [PRM = parameter_files/p10.prm] [SCENES = pressure:10000]
//                      [SIZES m = 0.008,0.0055,0.004,0.003] [WALL LAYERS = 1] [CSV]
// SCENES, comma-separated: pressure:P (Pa on the cavity), lateral:F (N along
// +z on the tip face), down:F (N along -y, in the bending plane).
// Scratch files (.prm, the ccx decks and their output) go to
// $TMPDIR/softchain_calculix_finger; CSV (if given) gets one row per mesh.
#include <calculix_deck.h>
#include <fem_test_tools.h>

#include <softchain/data/richardson_extrapolation.h>
#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/lone_process_mpi.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace softchain::fem;

namespace
{
  struct Mesh
  {
    double       size = 0;
    unsigned int dofs = 0;
    double       softchain_s = 0, calculix_s = 0;
    Tensor<1, 3> softchain_u, calculix_u; // mean tip displacement [m]
  };

  double seconds_since(const std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  std::string read_text(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      {
        std::fprintf(stderr, "calculix_finger: cannot read %s\n", file.c_str());
        std::exit(2);
      }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // The design's .prm with the mesh, the springs and the energy set for
  // the comparison (later `set` lines override earlier ones).
  std::string comparison_prm(const std::string &design, const double size, const unsigned int layers)
  {
    std::ostringstream prm;
    prm << design << "\nsubsection Finger design\n  set Element shape = hex\n  set Resolution = 0\n"
        << "  set Mesh sizes = " << size << ", " << size << ", " << size
        << "\n  set Wall layers = " << layers << "\nend\n"
        << "subsection Mesh\n  set Element type = Q2\nend\n"
        << "subsection Springs\n  set Axial rigidity = fabric: 0, thread: 0\nend\n"
        << "subsection Materials\n  set Strain energy = split\nend\n"
        << "subsection Contact\n  set Obstacles in solve = none\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Verbose = false\nend\n";
    return prm.str();
  }

  // sum_v a_v u(v) / sum_v a_v over the tip face's vertices, a_v their
  // area shares.
  template <typename Displacement>
  Tensor<1, 3> mean_over_tip(const Triangulation<3> &mesh, const Displacement &u)
  {
    Tensor<1, 3> sum;
    double       area = 0;
    for (const auto &[v, share] : test::tip_area_shares(mesh))
      {
        sum += share * u(v);
        area += share;
      }
    return sum / area;
  }

  // The scene as both codes' loads: pressure [Pa] and tip traction [N/m^2].
  struct Scene
  {
    std::string  name;
    double       pressure = 0;
    Tensor<1, 3> traction;
  };

  Scene scene_from(const std::string &text, const Triangulation<3> &mesh)
  {
    const auto   colon = text.find(':');
    Scene        scene;
    scene.name         = text.substr(0, colon);
    const double value = colon == std::string::npos ? 0 : std::atof(text.c_str() + colon + 1);
    double       area  = 0;
    for (const auto &[v, share] : test::tip_area_shares(mesh))
      area += share;
    if (scene.name == "pressure")
      scene.pressure = value;
    else if (scene.name == "lateral")
      scene.traction[2] = value / area;
    else if (scene.name == "down")
      scene.traction[1] = -value / area;
    if (colon == std::string::npos || !(value > 0) ||
        (scene.name != "pressure" && scene.name != "lateral" && scene.name != "down"))
      {
        std::fprintf(stderr, "calculix_finger: SCENE '%s' is not pressure:P, lateral:F or down:F (P, F > 0)\n",
                     text.c_str());
        std::exit(2);
      }
    return scene;
  }

  // SoftChain's solve of `scene` on the fixture's mesh; the time includes
  // the mesh and the solver's setup (from `start`).
  void softchain_solve(test::SolverFixture &f, const Scene &scene,
                       const std::chrono::steady_clock::time_point start, Mesh &mesh)
  {
    LoadState load;
    load.pressure     = scene.pressure;
    load.tip_traction = scene.traction;
    const auto result = f.solver->solve(load);
    mesh.softchain_s  = seconds_since(start);
    if (!result.converged)
      {
        std::fprintf(stderr, "SoftChain did not converge at %g m: %s\n", mesh.size, result.reason.c_str());
        std::exit(2);
      }
    mesh.dofs           = f.solver->space().dof_handler.n_dofs();
    const auto &vertices = f.mesh.triangulation.get_vertices();
    mesh.softchain_u    = mean_over_tip(f.mesh.triangulation, [&](unsigned int v) {
      return test::displacement_at(*f.solver, vertices[v]);
    });
  }

  // CalculiX's solve of `scene` on the same mesh: its deck and its run.
  void calculix_solve(const Triangulation<3> &finger, const Scene &scene, Mesh &mesh)
  {
    std::vector<unsigned int> tip;
    for (const auto &[v, share] : test::tip_area_shares(finger))
      tip.push_back(v);
    const auto         start = std::chrono::steady_clock::now();
    test::CalculixDeck deck;
    deck.element   = test::CalculixDeck::Element::C3D20R;
    deck.tolerance = 1e-6;
    deck.write("finger.inp", finger, {scene.traction[1], scene.pressure, scene.traction[2]}, tip);
    if (std::system("ccx -i finger > finger.log 2>&1") != 0)
      {
        std::fprintf(stderr, "ccx failed at %g m: see finger.log in the scratch directory\n", mesh.size);
        std::exit(2);
      }
    mesh.calculix_s = seconds_since(start);
    mesh.calculix_u = test::calculix_mean_tip_displacement("finger.dat", finger);
  }

  // Per component: the extrapolated value, or the finest mesh's. A
  // component that stays below 1 nm on all three meshes (the symmetric
  // scenes' z) is zero by symmetry, not a sequence to extrapolate.
  Tensor<1, 3> converged(const std::vector<Mesh> &meshes, Tensor<1, 3> Mesh::*u, bool &extrapolated)
  {
    const std::size_t n = meshes.size();
    std::array<double, 3> h;
    for (int k = 0; k < 3; ++k)
      h[k] = std::cbrt(1.0 / meshes[n - 1 - k].dofs);
    Tensor<1, 3> value;
    extrapolated = true;
    for (unsigned int i = 0; i < 3; ++i)
      {
        const std::array<double, 3> f = {{(meshes[n - 1].*u)[i], (meshes[n - 2].*u)[i], (meshes[n - 3].*u)[i]}};
        if (std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])}) < 1e-9)
          {
            value[i] = f[0];
            continue;
          }
        const auto estimate = softchain::data::RichardsonExtrapolation::of(h, f);
        extrapolated        = extrapolated && estimate.asymptotic;
        value[i]            = estimate.value;
      }
    return value;
  }

  // One scene on every mesh: the table, then each code's converged answer.
  std::vector<Mesh> run_scene(const std::string &design, const std::string &scene,
                              const std::vector<double> &sizes, const unsigned int layers, double &length)
  {
    std::vector<Mesh> meshes;
    std::printf("\n%s, Q2 / C3D20R, %u element(s) across the walls\n", scene.c_str(), layers);
    std::printf("%8s %7s %9s %9s %32s %32s %10s\n", "h [mm]", "DoFs", "sc [s]", "ccx [s]",
                "SoftChain mean tip u [mm]", "CalculiX mean tip u [mm]", "|diff| [mm]");
    for (const double size : sizes)
      {
        const auto start = std::chrono::steady_clock::now();
        Parameters prm   = test::parameters_from_text("calculix_finger", comparison_prm(design, size, layers));
        prm.contact      = prm.contact.solve_scene(); // no obstacle: CalculiX's deck has none
        length           = prm.finger_design->length();
        test::SolverFixture f(prm);
        const Scene         loads = scene_from(scene, f.mesh.triangulation);
        Mesh                mesh;
        mesh.size = size;
        softchain_solve(f, loads, start, mesh);
        calculix_solve(f.mesh.triangulation, loads, mesh);
        meshes.push_back(mesh);
        const Tensor<1, 3> a = 1e3 * mesh.softchain_u, b = 1e3 * mesh.calculix_u;
        std::printf("%8.2f %7u %9.2f %9.2f   (%8.4f, %8.4f, %8.4f)   (%8.4f, %8.4f, %8.4f) %10.4f\n",
                    1e3 * size, mesh.dofs, mesh.softchain_s, mesh.calculix_s, a[0], a[1], a[2], b[0],
                    b[1], b[2], (a - b).norm());
        std::fflush(stdout);
      }
    if (meshes.size() < 3)
      return meshes;
    bool               sc_extrapolated, ccx_extrapolated;
    const Tensor<1, 3> sc  = converged(meshes, &Mesh::softchain_u, sc_extrapolated);
    const Tensor<1, 3> ccx = converged(meshes, &Mesh::calculix_u, ccx_extrapolated);
    const auto report = [&](const char *code, const Tensor<1, 3> &u, bool extrapolated,
                            Tensor<1, 3> Mesh::*finest) {
      std::printf("%-9s converged mean tip u (%8.4f, %8.4f, %8.4f) mm (%s); finest mesh %.3f %% of L from it\n",
                  code, 1e3 * u[0], 1e3 * u[1], 1e3 * u[2],
                  extrapolated ? "Richardson" : "finest mesh where not in order",
                  100 * (meshes.back().*finest - u).norm() / length);
    };
    report("SoftChain", sc, sc_extrapolated, &Mesh::softchain_u);
    report("CalculiX", ccx, ccx_extrapolated, &Mesh::calculix_u);
    std::printf("SoftChain vs CalculiX converged: %.3f %% of L\n", 100 * (sc - ccx).norm() / length);
    return meshes;
  }

  std::vector<std::string> split(const std::string &list)
  {
    std::vector<std::string> items;
    std::stringstream        in(list);
    for (std::string item; std::getline(in, item, ',');)
      items.push_back(item);
    return items;
  }
} // namespace

int main(int argc, char **argv)
{
  use_the_cpus_blas_kernel(argv);
  use_no_network_transport_when_alone();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const std::string  prm_file = std::filesystem::absolute(argc > 1 ? argv[1] : "parameter_files/p10.prm");
  const auto         scenes   = split(argc > 2 ? argv[2] : "pressure:10000");
  const auto         sizes    = split(argc > 3 ? argv[3] : "0.008,0.0055,0.004,0.003");
  const unsigned int layers   = argc > 4 ? std::atoi(argv[4]) : 1;
  const std::string  csv      = argc > 5 ? std::filesystem::absolute(argv[5]).string() : "";
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    {
      std::fprintf(stderr, "ccx not found (scripts/setup installs calculix-ccx)\n");
      return 2;
    }
  const std::string design = read_text(prm_file);
  const auto scratch = std::filesystem::temp_directory_path() / "softchain_calculix_finger";
  std::filesystem::create_directories(scratch);
  std::filesystem::current_path(scratch);
  std::vector<double> mesh_sizes;
  for (const std::string &size : sizes)
    mesh_sizes.push_back(std::atof(size.c_str()));

  std::printf("%s without springs\n", prm_file.c_str());
  std::ofstream out;
  if (!csv.empty())
    {
      out.open(csv);
      out << "scene,mesh_size_mm,wall_layers,dofs,softchain_s,calculix_s,softchain_ux_mm,softchain_uy_mm,"
             "softchain_uz_mm,calculix_ux_mm,calculix_uy_mm,calculix_uz_mm,tip_displacement_percent_L,"
             "difference_percent_L\n";
    }
  for (const std::string &scene : scenes)
    {
      double length = 0;
      for (const Mesh &m : run_scene(design, scene, mesh_sizes, layers, length))
        if (out.is_open())
          {
            out << scene << ',' << 1e3 * m.size << ',' << layers << ',' << m.dofs << ',' << m.softchain_s
                << ',' << m.calculix_s;
            for (const Tensor<1, 3> &u : {m.softchain_u, m.calculix_u})
              for (unsigned int i = 0; i < 3; ++i)
                out << ',' << 1e3 * u[i];
            out << ',' << 100 * m.softchain_u.norm() / length << ','
                << 100 * (m.softchain_u - m.calculix_u).norm() / length << '\n';
          }
    }
  return 0;
}
