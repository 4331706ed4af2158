#include <softchain/data/content_hash.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/mesh_checks.h>
#include <softchain/geometry/reinforcement.h>
#include <softchain/geometry/spring_network_file.h>
#include <softchain/geometry/surface_import.h>

#include <filesystem>

namespace softchain::geometry
{
  namespace
  {
    // The -setnumber values of meshes/finger.geo.
    GmshJob finger_job(const FingerDesign &design)
    {
      const FingerDimensions &d = design.dimensions;
      GmshJob                 job;
      job.name    = design.source;
      job.script  = GmshJob::bundled_script("finger.geo");
      job.numbers = {{"L", d.length},          {"w_base", d.base_width}, {"h_base", d.base_height},
                     {"w_tip", d.tip_width},   {"h_tip", d.tip_height},  {"d", d.wall},
                     {"bottom", d.bottom},     {"fill", d.base_fill},    {"cap", d.tip_cap},
                     {"size", design.mesh_size()}, {"hex", design.hexahedra ? 1.0 : 0.0}};
      // Named only when they change the mesh (layers across the walls, a size
      // along the finger of its own), so that the job of an isotropic
      // one-layer design lists the numbers it always did.
      if (design.wall_layers > 1)
        job.numbers.push_back({"layers", static_cast<double>(design.wall_layers)});
      if (design.mesh_size_along() != design.mesh_size())
        job.numbers.push_back({"along", design.mesh_size_along()});
      return job;
    }

    std::vector<SpringNetwork> spring_networks(const FingerDesign &design)
    {
      if (design.parametric() && design.fibre_sheets)
        return {Reinforcement::fabric_sheet(design.dimensions, design.springs),
                Reinforcement::thread_sheets(design.dimensions, design.springs)};
      if (design.parametric())
        return {Reinforcement::fabric(design.dimensions, design.springs),
                Reinforcement::threads(design.dimensions, design.springs)};
      if (design.surface.spring_file.empty())
        return {};
      return SpringNetworkFile::read(design.surface.spring_file);
    }
  } // namespace

  GeneratedDesign generate_design(const FingerDesign &design, GmshMesher &mesher)
  {
    const GmshJob job = design.parametric() ? finger_job(design) : SurfaceImport::job(design);
    const auto    networks = spring_networks(design);
    GeneratedDesign result;
    result.mesh_file = mesher.mesh(job);
    result.hash      = data::content_hash(job.key() + "\n" + SpringNetworkFile::text(networks));
    result.length    = design.length();
    result.spring_file =
      (std::filesystem::path(result.mesh_file).parent_path() / ("springs-" + result.hash + ".txt"))
        .string();
    if (!std::filesystem::exists(result.spring_file))
      SpringNetworkFile::write(result.spring_file, networks);
    const std::string spring_source =
      design.parametric() ? result.spring_file : design.surface.spring_file;
    MeshChecks::check_all(MshFile::read(result.mesh_file), networks, spring_source);
    return result;
  }

  GeneratedDesign generate_design(const FingerDesign &design, const std::string &cache_dir)
  {
    GmshMesher mesher(cache_dir);
    return generate_design(design, mesher);
  }
} // namespace softchain::geometry
