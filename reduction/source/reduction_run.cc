// ReductionRun: parameters + database -> stiffness CSV files and plots.
#include <softchain/data/actuation_database.h>
#include <softchain/data/output_files.h>
#include <softchain/reduction/contact_force_table.h>
#include <softchain/reduction/joint_layout.h>
#include <softchain/reduction/method_reduction.h>
#include <softchain/reduction/neutral_layer.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/reduction_run.h>
#include <softchain/reduction/stiffness_plots.h>
#include <softchain/reduction/stiffness_tables.h>
#include <softchain/reduction/twist_axis.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace softchain::reduction
{
  namespace
  {
    // The converged samples but the contact samples (ContactForceTable
    // takes those); failed ones are skipped with a warning.
    std::vector<data::SampleRecord> converged_samples(const data::ActuationDatabase &database,
                                                      int                           &n_failed,
                                                      std::vector<data::SampleRecord> &contact)
    {
      std::vector<data::SampleRecord> converged;
      for (const auto &id : database.sample_ids())
        {
          data::SampleRecord sample = database.read_sample(id);
          if (ContactForceTable::is_contact(sample))
            contact.push_back(std::move(sample));
          else if (sample.converged())
            converged.push_back(std::move(sample));
          else
            {
              ++n_failed;
              std::cerr << "softchain reduce: warning: skipping failed sample '" << id
                        << "' (" << sample.reason << ")\n";
            }
        }
      return converged;
    }

    // The samples whose role feeds k_phi, at a nonzero pressure: they bend
    // the finger about z and locate its neutral layer.
    std::vector<const data::SampleRecord *> bending_samples(const ReductionParameters &parameters,
                                                            const std::vector<data::SampleRecord> &samples)
    {
      std::vector<const data::SampleRecord *> bending;
      for (const auto &sample : samples)
        if (sample.actuation.pressure != 0 &&
            std::count(parameters.pressure_roles.begin(), parameters.pressure_roles.end(),
                       sample.actuation.role))
          bending.push_back(&sample);
      return bending;
    }

    // The converged samples whose role feeds k_psi: they twist the finger
    // and locate its twist axis.
    std::vector<const data::SampleRecord *> torsion_samples(const ReductionParameters &parameters,
                                                            const std::vector<data::SampleRecord> &samples)
    {
      std::vector<const data::SampleRecord *> torsion;
      for (const auto &sample : samples)
        if (std::count(parameters.torsion_roles.begin(), parameters.torsion_roles.end(),
                       sample.actuation.role))
          torsion.push_back(&sample);
      return torsion;
    }

    // Builds the joint geometry of every b for the placement of the .prm.
    class GeometryFactory
    {
    public:
      GeometryFactory(const ReductionParameters &parameters, const JointLayout &layout,
                      const data::MeshRecord &mesh, const std::vector<data::SampleRecord> &samples,
                      const std::string &source)
        : layout_(layout)
        , mesh_(mesh)
      {
        if (parameters.placement == JointPlacement::paper)
          return;
        body_ = std::make_shared<const BodySamples>(
          mesh, layout.spacing() / lattice_points_per_spacing, source);
        layer_height_ = parameters.joint_height;
        if (std::isnan(layer_height_))
          {
            const NeutralLayer layer(body_, layout, mesh_, bending_samples(parameters, samples));
            layer_height_ = layer.height();
            std::cout << "softchain reduce: " << layer.description() << "\n";
          }
        twist_offset_ = parameters.twist_axis_offset;
        if (std::isnan(twist_offset_))
          {
            // Fitted on the links' own slabs (b = a/2), like the layer.
            const TwistAxis axis((*this)(0.5 * layout.spacing()), mesh_,
                                 torsion_samples(parameters, samples),
                                 body_->reference_box().max()(1) - layer_height_, source);
            twist_offset_ = axis.offset();
            std::cout << "softchain reduce: " << axis.description() << "\n";
          }
      }

      JointGeometry operator()(double half_width) const
      {
        if (!body_)
          return JointGeometry(layout_, mesh_, half_width);
        JointGeometry geometry(layout_, body_, layer_height_, half_width);
        geometry.set_twist_offset(std::isnan(twist_offset_) ? 0.0 : twist_offset_);
        return geometry;
      }

    private:
      const JointLayout                 &layout_;
      const data::MeshRecord            &mesh_;
      std::shared_ptr<const BodySamples> body_;
      double                             layer_height_ = NAN;
      double                             twist_offset_ = NAN;
    };

    // Writes the CSV files of every (b, method); returns their labels and
    // adds the counts of its warnings to `summary`.
    std::vector<std::string> write_tables(const ReductionParameters             &parameters,
                                          const GeometryFactory                 &geometry,
                                          double                                 spacing,
                                          const data::MeshRecord                &mesh,
                                          const std::vector<data::SampleRecord> &samples,
                                          const std::string &directory, ReductionSummary &summary)
    {
      std::vector<std::string> labels;
      for (const double fraction : parameters.slab_half_width_fractions)
        for (const auto method : parameters.methods)
          {
            const MethodReduction reduction(method, fraction, parameters,
                                            geometry(fraction * spacing), mesh, samples);
            const StiffnessTables tables(reduction, parameters);
            for (const std::string &warning : tables.write(directory))
              std::cerr << "softchain reduce: warning: " << reduction.label() << ": " << warning << '\n';
            labels.push_back(reduction.label());
            summary.n_below_threshold += reduction.stiffness().n_below_threshold();
            summary.n_past_limit += tables.joint_law().n_past_limit();
            summary.n_without_law += tables.joint_law().n_without_fit();
          }
      return labels;
    }

    bool draw_plots(const std::string &directory, const std::vector<std::string> &labels,
                    double spacing)
    {
      const bool drawn = StiffnessPlots(directory, labels, spacing).draw();
      if (!drawn)
        std::cerr << "softchain reduce: warning: no PNG plots (gnuplot missing or failed, see "
                  << directory << "/plots.log); the script is " << directory << "/plots.gp\n";
      return drawn;
    }
  } // namespace

  ReductionRun::ReductionRun(const data::PrmFile &prm, std::string database_path,
                             std::string output_dir)
    : parameters_(ReductionParameters::read(prm))
    , database_path_(std::move(database_path))
    , output_dir_(std::move(output_dir))
  {}

  ReductionSummary ReductionRun::run() const
  {
    const auto &parameters = parameters_;
    const auto database   = data::ActuationDatabase::open(database_path_);
    const JointLayout layout(database.mesh().X, parameters.joint_spacing, parameters.n_joints,
                             database_path_);
    ReductionSummary summary;
    std::vector<data::SampleRecord> contact;
    const auto samples     = converged_samples(database, summary.n_failed_skipped, contact);
    summary.n_samples_used = static_cast<int>(samples.size());
    ContactForceTable(contact, database.mesh(), database_path_).write(data::contact_forces_file(output_dir_));
    const std::string directory = output_dir_ + "/" + data::folder::stiffness;
    std::filesystem::create_directories(directory);
    const GeometryFactory geometry(parameters, layout, database.mesh(), samples, database_path_);
    const auto labels = write_tables(parameters, geometry, layout.spacing(), database.mesh(),
                                     samples, directory, summary);
    if (summary.n_below_threshold > 0)
      std::cerr << "softchain reduce: warning: " << summary.n_below_threshold
                << " (sample, joint, axis) rotations over all methods and b are below "
                   "Reduction/Rotation threshold = "
                << parameters.rotation_threshold
                << " rad or carry no torque, and give no stiffness (nan)\n";
    if (summary.n_past_limit > 0)
      std::cerr << "softchain reduce: warning: joint law: " << summary.n_past_limit
                << " (sample, joint) force increments over all methods and b lie past a limit "
                   "point (the FEM passed a limit point of the forces on the way, or the joint "
                   "turns or loads less than under a lighter force of the same kind, as past "
                   "sideways buckling) and are not fitted: the joint law stops at the limit\n";
    if (summary.n_without_law > 0)
      std::cerr << "softchain reduce: warning: joint law: " << summary.n_without_law
                << " (joint, pressure) pairs over all methods and b have no fabric-hinge law (no "
                   "positive fit, one missing the torques by more than 15 %, or, inflated, none "
                   "whose knee the lateral samples pass: reduction/README.md); the chain keeps "
                   "linear springs there\n";
    if (parameters.plots)
      summary.plots_drawn = draw_plots(directory, labels, parameters.joint_spacing);
    return summary;
  }

  int run_reduction(const data::PrmFile &prm, const std::string &database_path,
                    const std::string &output_dir)
  {
    ReductionRun(prm, database_path, output_dir).run();
    return 0;
  }
} // namespace softchain::reduction
