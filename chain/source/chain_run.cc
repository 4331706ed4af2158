#include <softchain/chain/beam_theory_baseline.h>
#include <softchain/chain/chain_parameters.h>
#include <softchain/chain/chain_run.h>
#include <softchain/chain/chain_validation.h>
#include <softchain/chain/finger_collision_surface.h>
#include <softchain/chain/mjcf_export.h>
#include <softchain/chain/mujoco_tip_distances.h>
#include <softchain/chain/protocol_plot.h>
#include <softchain/chain/protocol_torques.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/output_files.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/chain/validation_plot.h>
#include <softchain/data/input_error.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace softchain::chain
{
  namespace
  {
    // Reference extent of the mesh: (min, max) corner of the bounding box.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> bounding_box(const data::MeshRecord &mesh)
    {
      Eigen::Vector3d low  = Eigen::Vector3d::Constant(INFINITY);
      Eigen::Vector3d high = -low;
      for (const data::Point3 &p : mesh.X)
        {
          const Eigen::Vector3d x(p[0], p[1], p[2]);
          low  = low.cwiseMin(x);
          high = high.cwiseMax(x);
        }
      return {low, high};
    }

    // A compliance set in the .prm: the same at every pressure (none for 0).
    std::optional<PiecewiseLinear> constant_compliance(const double c)
    {
      if (c > 0.0)
        return PiecewiseLinear({0.0}, {c});
      return std::nullopt;
    }

    // M1 and M2 (the selected one required, the other if present).
    std::vector<ChainModel> read_models(const std::string &directory, const ChainParameters &p,
                                        const Eigen::Vector3d &tip)
    {
      std::vector<ChainModel> models;
      const auto read = [&](const StiffnessFiles &files, const std::string &name) {
        ChainModel model =
          files.read_model(name, tip, p.stiffness_column, p.in_pressure, p.rigid_where_missing);
        if (!p.measured_joint_law)
          model = model.with_linear_joints();
        if (p.skin_compliance)
          model.set_skin_compliance(constant_compliance(*p.skin_compliance));
        if (p.skin_shear_compliance)
          model.set_skin_shear_compliance(constant_compliance(*p.skin_shear_compliance));
        if (!p.pressure_link_geometry)
          return model.with_rigid_links();
        if (!p.link_shift)
          model = model.without_link_shift();
        else if (!std::filesystem::exists(files.link_shift_path()))
          throw data::InputError(files.link_shift_path() + " is missing, and Chain/Link shift = measured needs "
                                 "it: run softchain reduce again, or set Link shift = none");
        else if (!model.has_link_shift())
          std::cout << "chain: warning: " << files.link_shift_path() << " gives " << name
                    << " no shifts (no in-plane force samples, or no link geometry); its links do not shift\n";
        return p.link_compliance ? model : model.without_link_compliance();
      };
      for (const auto &[name, method] : data::rotation_methods())
        {
          const StiffnessFiles files(directory, method, p.half_width_fraction);
          if (method == p.method)
            models.push_back(read(files, name));
          else if (!files.exist())
            std::cout << "chain: no " << files.stiffness_path() << ", " << name << " skipped\n";
          else
            try // the other method is a comparison only: unusable files skip it
              {
                models.push_back(read(files, name));
              }
            catch (const data::InputError &e)
              {
                std::cout << "chain: " << name << " skipped: " << e.what() << '\n';
              }
        }
      return models;
    }

    ChainModel baseline_of(const ChainModel &selected, const data::MeshRecord &mesh, double E)
    {
      std::vector<double> joint_x;
      for (int i = 0; i < selected.chain().n_joints(); ++i)
        joint_x.push_back(selected.chain().joint_centre(i).x());
      return ChainModel("baseline", selected.chain(), BeamTheoryBaseline(mesh, joint_x).stiffness(E),
                        selected.actuation());
    }

    double max_pressure(const data::ActuationDatabase &database)
    {
      double p = 0.0;
      for (const std::string &id : database.sample_ids())
        p = std::max(p, database.read_sample(id).actuation.pressure);
      return p;
    }

    // MuJoCo's finger at rest in the MJCF at `path` against `model`'s at 11
    // pressures 0, p*/10, ..., p*, set from the pressure tables and as plain
    // MuJoCo (exact at p* only), in % of the finger's length L; the last line
    // is the largest distance over the pressures set from the tables.
    void compare_with_mujoco(const ChainModel &model, const std::string &path, const double p_star,
                             const double L, const EquilibriumSettings &settings)
    {
      std::vector<double> pressures;
      for (int i = 0; i <= 10; ++i)
        pressures.push_back(p_star * i / 10);
      const auto precision = std::cout.precision(3);
      double     max       = 0.0;
      for (const MujocoTipDistance &d : mujoco_tip_distances(model, path, pressures, settings))
        {
          std::cout << "chain: MuJoCo at rest at " << d.pressure / 1e3 << " kPa: tip " << 100 * d.with_tables / L
                    << " % of L from the chain's (plain MuJoCo, K, J_p and links of " << p_star / 1e3
                    << " kPa: " << 100 * d.exported_constants / L << " %)\n";
          max = std::max(max, d.with_tables);
        }
      std::cout << "mujoco vs chain over pressure: max tip distance " << 100 * max / L << " % of L\n";
      std::cout.precision(precision);
    }

    // The MJCF of `model` with K, J_p and the links at the database's largest
    // pressure p* and the pressure tables up to p*, compared with the chain.
    void export_model(const ChainModel &model, const data::ActuationDatabase &database,
                      const std::string &path, const EquilibriumSettings &settings)
    {
      const auto  box = bounding_box(database.mesh());
      MjcfOptions options;
      // Capsules as thick as the finger's thinner dimension (height or width).
      options.link_radius  = 0.5 * (box.second - box.first).tail<2>().minCoeff();
      options.max_pressure = max_pressure(database);
      options.pressure     = options.max_pressure;
      // Two capsules per link a quarter of the finger's width to each side
      // of its middle: inside the palm at the narrowest tip (P10: +-5 mm
      // against a tip 16 mm wide), and a finger pressed hard on a table
      // does not roll over on them (docs/chain_fidelity.md, "Contact in MuJoCo").
      options.capsule_offset = 0.25 * (box.second - box.first).z();
      // A link gives where its middle lies over the cavity (the collision
      // surface's points that give, per link).
      const auto           span  = cavity_span(database.mesh());
      const KinematicChain links = model.chain();
      for (int i = 0; i < links.n_joints(); ++i)
        {
          const double middle =
            0.5 * (links.link_joint(i).x() + (i + 1 < links.n_joints() ? links.link_joint(i + 1) : links.link_tip()).x());
          options.skin_links.push_back(middle > span.first && middle < span.second);
        }
      MjcfExport(model.with_name(database.design().name + "_" + model.name()), options).write(path);
      std::cout << "chain: MuJoCo model " << path << "\n";
      compare_with_mujoco(model, path, options.pressure, box.second.x() - box.first.x(), settings);
    }

    // The FEM's outer surface on every model's links: shaped by the pressure
    // where the links are, rigid otherwise (the baseline). Only if the
    // database holds contact samples.
    void add_collision_surfaces(std::vector<ChainModel> &models, const data::ActuationDatabase &database,
                                const ChainParameters &p)
    {
      const SurfaceSamples samples = SurfaceSamples::read(database);
      if (!samples.contact)
        return;
      for (ChainModel &model : models)
        model.set_collision_surface(model.has_link_geometry()
                                      ? pressure_shaped_collision_surface(model, database.mesh(), samples.inflated,
                                                                          p.newton, p.surface_subdivisions)
                                      : rigid_collision_surface(model, database.mesh(), p.surface_subdivisions));
      if (!models.empty())
        std::cout << "chain: collision surface of " << models.front().collision_surface()->n_points()
                  << " points (Chain/Surface subdivisions = " << p.surface_subdivisions << ")\n";
    }

    // Blocked force and grasp per model, if there are contact samples;
    // without, an earlier run's summary is removed (the report reads it).
    void report_contact(const ChainValidation &validation, const std::string &file)
    {
      const data::CsvTable summary = validation.grasp_summary_table();
      if (summary.n_rows() == 0)
        {
          std::filesystem::remove(file);
          return;
        }
      summary.write(file);
      const auto precision = std::cout.precision(3);
      for (std::size_t r = 0; r < summary.n_rows(); ++r)
        std::cout << "chain: " << summary.text(r, "model") << " in contact: blocked force error "
                  << error_percent(summary.number(r, "blocked_force_error_percent")) << ", grasp force error "
                  << error_percent(summary.number(r, "grasp_force_error_percent")) << ", tip "
                  << summary.number(r, "tip_error_percent_L") << " % of L and "
                  << summary.number(r, "orientation_error_deg") << " deg (max over "
                  << summary.text(r, "n_samples") << " samples, " << summary.text(r, "n_failed")
                  << " failed); median solve " << summary.number(r, "median_solve_time_us") << " us\n";
      std::cout.precision(precision);
    }

    void report(const ChainValidation &validation, const std::string &directory)
    {
      const data::CsvTable summary   = validation.summary_table();
      const auto           precision = std::cout.precision(3);
      for (std::size_t r = 0; r < summary.n_rows(); ++r)
        std::cout << "chain: " << summary.text(r, "model") << " on " << summary.text(r, "roles")
                  << ": tip error max " << summary.number(r, "max_tip_error_percent_L")
                  << " % of L, mean " << summary.number(r, "mean_tip_error_percent_L")
                  << " %; orientation max " << summary.number(r, "max_orientation_error_deg")
                  << " deg (" << summary.text(r, "n_samples") << " samples, "
                  << summary.text(r, "n_failed") << " failed)\n";
      for (const ValidationRecord &r : validation.records())
        if (!r.converged)
          std::cerr << "chain: " << r.model << " failed on sample " << r.sample << ": " << r.failure
                    << "\n";
      std::cout << "chain: tables in " << directory << "\n";
      std::cout.precision(precision);
    }

    // Every model against the database's FEM tip poses: tables, plot, report;
    // returns the number of failed chain equilibria of the selected model
    // (the other method and the baseline are comparisons: their failures are
    // reported, not an error of the run).
    int validate(const std::vector<ChainModel> &models, ChainValidation &validation,
                 const ChainParameters &p, const data::ChainFileSet &files)
    {
      const std::string       &directory = files.directory;
      std::vector<std::string> names;
      for (const ChainModel &model : models)
        {
          validation.compare(model, p.newton, p.friction_path, p.timed_solves);
          names.push_back(model.name());
        }
      if (validation.records().empty())
        std::cout << "chain: no converged database sample has one of the validation roles\n";
      validation.per_sample_table().write(files.validation);
      validation.summary_table().write(files.validation_summary);
      validation.pose_table().write(files.chain_poses);
      report_contact(validation, files.grasp_summary);
      if (!ValidationPlot(directory, names).draw())
        std::cout << "chain: gnuplot missing or failed, validation.png not drawn (script validation.gp)\n";
      report(validation, directory);
      return validation.n_failed(data::method_name(p.method));
    }

    // The paper's validation experiment, if the database holds its samples:
    // base torque traces and their errors per model (tables, plot, lines).
    // Without, an earlier protocol's tables and plot are removed (the report
    // reads them).
    void compare_protocol(const std::vector<ChainModel> &models,
                          const data::ActuationDatabase &database, const ChainParameters &p,
                          const data::ChainFileSet &files)
    {
      const std::string &directory = files.directory;
      // The sweep lists the protocol's samples beside the database.
      ProtocolTorques protocol(
        database, (std::filesystem::path(database.path()).parent_path() / "protocol_samples.csv").string());
      if (protocol.empty())
        {
          for (const std::string &file : {files.protocol_torques, files.protocol_summary, files.protocol_plot,
                                          files.protocol_plot_script})
            std::filesystem::remove(file);
          return;
        }
      for (const ChainModel &model : models)
        protocol.compare(model, p.newton);
      protocol.trace_table().write(files.protocol_torques);
      const data::CsvTable summary = protocol.summary_table();
      summary.write(files.protocol_summary);
      if (!draw_protocol_plot(directory, protocol.models()))
        std::cout << "chain: gnuplot missing or failed, protocol_torques.png not drawn\n";
      const auto precision = std::cout.precision(3);
      for (std::size_t r = 0; r < summary.n_rows(); r += 3)
        {
          std::cout << "chain: tip-motion protocol at " << protocol.pressure() << " Pa, "
                    << summary.text(r, "model") << ": base torque RMS error";
          for (std::size_t c = r; c < r + 3; ++c)
            std::cout << (c > r ? ", " : " ") << summary.text(c, "torque") << " "
                      << summary.number(c, "rms_error_percent_range") << " %";
          std::cout << " of the FEM's range\n";
        }
      std::cout.precision(precision);
      for (const std::string &failure : protocol.failures())
        std::cerr << "chain: protocol: " << failure << "\n";
    }
  } // namespace

  int run_chain(const data::PrmFile &prm, const std::string &database_path,
                const std::string &output_dir, bool export_mjcf)
  {
    const ChainParameters          p        = ChainParameters::read(prm);
    const data::ActuationDatabase  database = data::ActuationDatabase::open(database_path);
    const data::MeshRecord        &mesh     = database.mesh();
    const std::string stiffness_dir = (std::filesystem::path(output_dir) / data::folder::stiffness).string();
    const data::ChainFileSet files(output_dir);

    // The FEM tip poses first: they need no chain model.
    const auto      box = bounding_box(mesh);
    ChainValidation validation(database, p.validation_roles, box.second.x() - box.first.x());
    std::filesystem::create_directories(files.directory);
    validation.fem_tip_table().write(files.fem_tip_poses);

    std::vector<ChainModel> models = read_models(
      stiffness_dir, p, data::TipPoseFit::of_mesh(mesh, database.path()).reference_centroid());
    const ChainModel        selected =
      *std::find_if(models.begin(), models.end(),
                    [&](const auto &m) { return m.name() == data::method_name(p.method); });
    // The baseline's beam segments lie between the joints of the reduction's
    // table, each joint one spherical joint (no separate twist axis).
    const ChainModel plain = StiffnessFiles(stiffness_dir, p.method, p.half_width_fraction)
                               .read_model(selected.name(), selected.chain().tip(), p.stiffness_column,
                                           p.in_pressure, p.rigid_where_missing, false);
    models.push_back(baseline_of(plain, mesh, p.baseline_youngs_modulus));
    add_collision_surfaces(models, database, p);
    const int failed = validate(models, validation, p, files);
    compare_protocol(models, database, p, files);
    if (export_mjcf)
      export_model(selected, database, files.mjcf, p.newton);
    return failed > 0 ? 2 : 0;
  }
} // namespace softchain::chain
