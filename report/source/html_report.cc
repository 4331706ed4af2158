#include <softchain/chain/stiffness_files.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/report/report_numbers.h>
#include <softchain/report/base64.h>
#include <softchain/report/html_report.h>
#include <softchain/report/paper_claims.h>
#include <softchain/report/pressure_snapshots.h>
#include <softchain/report/surface_mesh.h>
#include <softchain/report/obstacle_outline.h>
#include <softchain/report/svg_curve_plot.h>
#include <softchain/report/svg_finger_renderer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

namespace softchain::report
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string read_bytes(const std::string &path)
    {
      std::ifstream      in(path, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      return bytes.str();
    }


    // Throws the InputError of a missing input, naming the command that
    // writes it.
    void require(const std::string &path, const std::string &writer)
    {
      if (!fs::exists(path))
        throw data::InputError(path + ": not found (written by `softchain " + writer +
                               "`; run it, or `softchain run`, first)");
    }


    // The largest point force [N]: the tip force of a lateral sample, each
    // force of a torsion couple (whose sum is zero).
    double largest_force(const data::Actuation &actuation)
    {
      double largest = 0;
      for (const auto &f : actuation.point_forces)
        largest = std::max(largest, std::hypot(f.force[0], f.force[1], f.force[2]));
      return largest;
    }
  } // namespace

  HtmlReport::HtmlReport(const data::PrmFile &prm, const std::string &database_path,
                         const std::string &output_directory)
    : output_directory_(output_directory)
    , chain_(chain::ChainParameters::read(prm))
  {
    require(database_path, "sweep");
    require(data::StiffnessFileSet(output(data::folder::stiffness), chain_label()).table, "reduce");
    const auto database = data::ActuationDatabase::open(database_path);
    design_             = database.design();
    mesh_               = database.mesh();
    for (const auto &id : database.sample_ids())
      samples_.push_back(database.read_sample(id));
  }

  std::string HtmlReport::output(const std::string &relative) const
  {
    return output_directory_ + "/" + relative;
  }

  std::string HtmlReport::chain_label() const
  {
    return chain::StiffnessFiles::label(chain_.method, chain_.half_width_fraction);
  }

  void HtmlReport::png_figure(HtmlDocument &page, const std::string &relative,
                              const std::string &caption) const
  {
    const std::string path = output(relative);
    if (fs::exists(path))
      page.figure(data_uri("image/png", read_bytes(path)), caption);
    else
      page.paragraph(caption + ": not drawn (" + path + " is missing: gnuplot not installed, or "
                                                        "Plots = false in subsection Reduction).");
  }

  // The FEM's own error, beside the chain's: fem_accuracy.csv of
  // `softchain accuracy` (its last row holds the converged estimate and,
  // in the distance column, that estimate's uncertainty).
  void HtmlReport::fem_accuracy_paragraph(HtmlDocument &page) const
  {
    const std::string path = output_directory_ + "/fem_accuracy.csv";
    if (!fs::exists(path))
      {
        page.paragraph("The FEM's discretisation error is not estimated for this design (run "
                       "`softchain accuracy` on its .prm; docs/fem_accuracy.md).");
        return;
      }
    const auto        table = data::CsvTable::read(path);
    const std::size_t last  = table.n_rows() - 1;
    const auto &columns = table.columns();
    if (std::find(columns.begin(), columns.end(), "design_hash") == columns.end() ||
        table.text(0, "design_hash") != design_.design_hash)
      {
        page.paragraph("The FEM's discretisation error is not shown: " + path +
                       " is of another design than this database's (" + design_.design_hash +
                       "); run `softchain accuracy` on this .prm again.");
        return;
      }
    page.paragraph("FEM discretisation error (softchain accuracy, at the .prm's Loads): the design's "
                   "mesh lies " + fmt(table.number(0, "distance_to_converged_percent_L")) +
                   " % of L from the mesh-converged answer, which is uncertain to " +
                   fmt(table.number(last, "distance_to_converged_percent_L")) +
                   " % of L. The chain's errors below are against the design's own FEM.");
  }

  // The answer first: how far the chain and the baseline land from the FEM,
  // and what one FEM sample and one chain equilibrium cost.
  void HtmlReport::summary_section(HtmlDocument &page) const
  {
    page.heading("Summary");
    std::vector<double> fem_times;
    int                 failed = 0;
    for (const auto &s : samples_)
      {
        fem_times.push_back(s.wall_time);
        failed += !s.converged();
      }
    page.paragraph(std::to_string(samples_.size()) + " FEM samples (" + std::to_string(failed) +
                   " failed), median " + fmt(median(fem_times)) + " s of wall time per sample. Chain: " +
                   data::method_name(chain_.method) + " at b = " + fmt(chain_.half_width_fraction) + " a.");
    fem_accuracy_paragraph(page);
    if (!fs::exists(data::ChainFileSet(output_directory_).validation_summary))
      {
        page.paragraph("No chain validation (chain/validation_summary.csv is missing; see section 4).");
        return;
      }
    const auto summary = data::CsvTable::read(data::ChainFileSet(output_directory_).validation_summary);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < summary.n_rows(); ++r)
      if (summary.text(r, "model") == data::method_name(chain_.method) || summary.text(r, "model") == "baseline")
        rows.push_back({summary.text(r, "model"), summary.text(r, "roles"), summary.text(r, "n_samples"),
                        summary.text(r, "n_failed"), fmt(summary.number(r, "max_tip_error_percent_L")),
                        fmt(summary.number(r, "mean_tip_error_percent_L")),
                        fmt(summary.number(r, "max_orientation_error_deg"))});
    page.table({"model", "samples", "n", "failed", "max tip error [% L]", "mean tip error [% L]",
                "max orientation error [deg]"},
               rows);
    if (fs::exists(data::ChainFileSet(output_directory_).validation))
      {
        const auto          records = data::CsvTable::read(data::ChainFileSet(output_directory_).validation);
        std::vector<double> times;
        for (std::size_t r = 0; r < records.n_rows(); ++r)
          if (records.text(r, "model") == data::method_name(chain_.method))
            times.push_back(records.number(r, "solve_time_us"));
        page.paragraph("One chain equilibrium from rest: median " + fmt(median(times)) + " µs.");
      }
  }

  void HtmlReport::design_section(HtmlDocument &page) const
  {
    page.heading("1. The design");
    page.table({"name", "element", "nodes", "cells", "design hash", "code version"},
               {{design_.name, design_.element_type, std::to_string(mesh_.X.size()),
                 std::to_string(mesh_.cells.size() / mesh_.nodes_per_cell) +
                   (mesh_.nodes_per_cell == 4 ? " tetrahedra" : " hexahedra"),
                 design_.design_hash, design_.code_version}});
    page.paragraph("The design's .prm file, as stored in the database's /design record:");
    page.preformatted(design_.parameters);
  }

  void HtmlReport::finger_section(HtmlDocument &page) const
  {
    page.heading("2. The deformed finger");
    const SurfaceMesh surface(mesh_);
    SvgFingerRenderer renderer(surface, mesh_.X);
    const auto snapshots = pressure_snapshots(mesh_.X, samples_, {0.0, 40e3, 80e3});
    for (const auto &snapshot : snapshots)
      renderer.include(snapshot.x);
    page.paragraph("The " + std::to_string(surface.faces().size()) +
                   " boundary faces of the mesh (corner nodes; quadratic faces drawn flat) at the "
                   "converged pressure-only samples nearest to 0, 40 and 80 kPa, over the rest "
                   "shape in grey. Oblique parallel view from +z, above and toward the tip; the "
                   "finger bends toward −y. All three pictures share one scale.");
    for (const auto &snapshot : snapshots)
      {
        const std::string title = fmt(snapshot.pressure / 1e3) + " kPa" +
                                  (snapshot.at_request ? "" : " (" + fmt(snapshot.requested / 1e3) +
                                                                " kPa requested, see below)");
        page.figure(data_uri("image/svg+xml", renderer.render(snapshot.x, title)), snapshot.caption);
      }
  }

  void HtmlReport::stiffness_section(HtmlDocument &page) const
  {
    page.heading("3. Stiffness profiles (the paper's Fig. 5–7)");
    png_figure(page, "stiffness/kphi_methods_and_b.png",
               "Fig. 5c equivalent: k_φ along the finger at the largest load, every method and b");
    png_figure(page, "stiffness/kpsi.png", "Fig. 5d equivalent: torsional stiffness k_ψ along the finger");
    png_figure(page, "stiffness/ktheta.png", "Fig. 7 equivalent: lateral stiffness k_θ along the finger");
    // One k_phi(x) plot per method and b, in file-name order.
    std::set<std::string> labels;
    const std::regex      table("(M[12]_b[0-9.]+a)\\.csv");
    for (const auto &entry : fs::directory_iterator(output("stiffness")))
      {
        std::smatch      match;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, match, table))
          labels.insert(match[1]);
      }
    for (const auto &label : labels)
      png_figure(page, "stiffness/" + label + "_kphi_vs_x.png",
                 "Fig. 5a/5b/6 equivalent: k_φ along the finger, one curve per pressure (" + label + ")");
    page.paragraph("The chain's stiffness table, stiffness/" + chain_label() +
                   ".csv (k in N m/rad, positions in m; nan: no value, e.g. a joint in the solid base):");
    page.table(data::CsvTable::read(data::StiffnessFileSet(output(data::folder::stiffness), chain_label()).table));
  }

  void HtmlReport::validation_section(HtmlDocument &page) const
  {
    page.heading("4. Chain against FEM");
    if (!fs::exists(data::ChainFileSet(output_directory_).validation_summary))
      {
        page.paragraph("No chain validation: chain/validation_summary.csv is missing. The chain "
                       "stage did not run or could not build a chain from the stiffness tables "
                       "(its message names the file and the joint, e.g. no positive stiffness "
                       "at any joint); `softchain chain` reruns it.");
        return;
      }
    const auto summary = data::CsvTable::read(data::ChainFileSet(output_directory_).validation_summary);
    page.paragraph("chain/validation_summary.csv: tip position errors (mm and % of the length L) "
                   "and tip orientation errors per model and sample role.");
    page.table(summary);
    png_figure(page, "chain/validation.png", "Chain and baseline tip poses against the FEM's");
    // Each model against the beam-theory baseline on the same roles.
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < summary.n_rows(); ++r)
      for (std::size_t b = 0; b < summary.n_rows(); ++b)
        if (summary.text(r, "model") != "baseline" && summary.text(b, "model") == "baseline" &&
            summary.text(b, "roles") == summary.text(r, "roles"))
          {
            const double mean = summary.number(r, "mean_tip_error_percent_L"),
                         max  = summary.number(r, "max_tip_error_percent_L"),
                         base_mean = summary.number(b, "mean_tip_error_percent_L"),
                         base_max  = summary.number(b, "max_tip_error_percent_L");
            rows.push_back({summary.text(r, "model"), summary.text(r, "roles"), fmt(mean), fmt(base_mean),
                            fmt(base_mean / mean), fmt(max), fmt(base_max), fmt(base_max / max)});
          }
    page.heading("Baseline comparison", 3);
    page.paragraph("Tip position errors in % of L; a ratio is the baseline's error over the chain's "
                   "(how many times more accurate the chain is).");
    page.table({"model", "roles", "mean", "baseline mean", "ratio of means", "max", "baseline max",
                "ratio of maxima"},
               rows);
    chain_pictures(page);
  }

  // The selected chain (chain/chain_poses.csv) drawn over the deformed FEM
  // finger of every validation sample, by increasing load.
  void HtmlReport::chain_pictures(HtmlDocument &page) const
  {
    page.heading("The chain over the FEM finger", 3);
    if (!fs::exists(data::ChainFileSet(output_directory_).chain_poses))
      {
        page.paragraph("chain/chain_poses.csv is missing: `softchain chain` writes it.");
        return;
      }
    const auto poses = data::CsvTable::read(data::ChainFileSet(output_directory_).chain_poses);
    std::vector<const data::SampleRecord *> shown;
    for (const auto &s : samples_)
      if (s.converged() && s.actuation.role == "validation")
        shown.push_back(&s);
    std::sort(shown.begin(), shown.end(), [](const auto *a, const auto *b) {
      return std::make_pair(a->actuation.pressure, largest_force(a->actuation)) <
             std::make_pair(b->actuation.pressure, largest_force(b->actuation));
    });
    const SurfaceMesh surface(mesh_);
    SvgFingerRenderer renderer(surface, mesh_.X);
    for (const auto *s : shown)
      renderer.include(s->x);
    page.paragraph("The " + data::method_name(chain_.method) + " chain's joints and tip (red) at its equilibrium under "
                   "each validation sample's load, over the FEM finger under the same load.");
    for (const auto *s : shown)
      {
        std::vector<Eigen::Vector3d> chain;
        for (std::size_t r = 0; r < poses.n_rows(); ++r)
          if (poses.text(r, "sample") == s->id && poses.text(r, "model") == data::method_name(chain_.method))
            chain.emplace_back(poses.number(r, "x"), poses.number(r, "y"), poses.number(r, "z"));
        const std::string title = fmt(s->actuation.pressure / 1e3) + " kPa, largest force " +
                                  fmt(largest_force(s->actuation)) + " N";
        page.figure(data_uri("image/svg+xml", renderer.render(s->x, title, chain)),
                    "sample " + s->id + (chain.empty() ? " (no chain equilibrium)" : ""));
      }
  }

  void HtmlReport::protocol_section(HtmlDocument &page) const
  {
    page.heading("5. Prescribed tip motion, base torques (the paper's Sec. IV-B, Fig. 10–11)");
    if (!fs::exists(data::ChainFileSet(output_directory_).protocol_summary))
      {
        page.paragraph("No tip-motion protocol: the design has none (subsection Protocol, Tip angle "
                       "= 0), so the database holds no protocol samples and `softchain chain` wrote "
                       "no chain/protocol_summary.csv.");
        return;
      }
    page.paragraph("The paper's validation experiment. The finger is inflated until its tip has "
                   "turned by the target angle (subsection Protocol, Tip angle); then its tip is "
                   "moved, each step one FEM sample: left and right (±z of the inflated tip "
                   "frame) and down and up (±y) by a point contact (the face free to turn, as a "
                   "chopstick holds it; or the face held, Tip contact = face), and twisted (±x) "
                   "with the face held. The FEM's base torques Tx, Ty, Tz "
                   "(the moment the finger exerts on its clamped base, about the base face's "
                   "centroid, world axes) are the ground truth. Each chain model (M1, M2 and the "
                   "beam-theory baseline k_θ = k_φ, k_ψ = 4 k_φ) is driven through the same "
                   "motions from its own inflated state, its tip point held and, where the FEM "
                   "held the face, its tip frame too (the FEM-based chains' links give in series "
                   "with their joints where chord samples measured them); the error of a "
                   "torque is the RMS over the trace of the chain's minus the FEM's, in % of the "
                   "FEM's range (max − min) of that torque over the trace. The paper found Tx "
                   "almost the same for its models and the baseline, Ty too soft, and the baseline "
                   "greatly overestimating Tz.");
    const auto summary = data::CsvTable::read(data::ChainFileSet(output_directory_).protocol_summary);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < summary.n_rows(); ++r)
      rows.push_back({summary.text(r, "model"), summary.text(r, "torque"),
                      fmt(1e3 * summary.number(r, "fem_range_Nm")), fmt(1e3 * summary.number(r, "rms_error_Nm")),
                      fmt(summary.number(r, "rms_error_percent_range")),
                      fmt(summary.number(r, "max_error_percent_range")), summary.text(r, "n_failed_points")});
    page.paragraph("chain/protocol_summary.csv; failed points: trace points without a chain "
                   "equilibrium, left out of the errors (a state the trace visits twice counts twice).");
    page.table({"model", "torque", "FEM range [mN m]", "RMS error [mN m]", "RMS error [% of range]",
                "max error [% of range]", "failed points"},
               rows);
    png_figure(page, "chain/protocol_torques.png", "Base torques over the protocol's trace, FEM and chains");
    // The trace's length and its inflation pressure (that of its samples).
    std::string trace;
    if (fs::exists(data::ChainFileSet(output_directory_).protocol_torques))
      {
        const auto torques = data::CsvTable::read(data::ChainFileSet(output_directory_).protocol_torques);
        trace = " (" + std::to_string(torques.n_rows()) + " steps";
        if (torques.n_rows() > 0)
          for (const auto &s : samples_)
            if (s.id == torques.text(0, "sample"))
              trace += ", inflated at " + fmt(s.actuation.pressure / 1e3) + " kPa";
        trace += ")";
      }
    page.paragraph("chain/protocol_torques.csv holds the trace step by step" + trace +
                   ": the motion (lateral, bending, twist), its amount (mm or deg), the FEM sample, "
                   "the FEM's Tx, Ty, Tz and each model's, in N m (nan where a chain equilibrium "
                   "failed).");
  }

  // The contact samples (contact/contact_forces.csv, ContactForceTable):
  // the force each obstacle receives against the pressure, the table of it,
  // and the finger against each obstacle at its highest converged pressure.
  void HtmlReport::contact_section(HtmlDocument &page) const
  {
    page.heading("6. Contact: blocked force and grasp");
    const std::string path = data::contact_forces_file(output_directory_);
    const std::string file = fs::relative(path, output_directory_).string();
    if (!fs::exists(path))
      {
        page.paragraph("No contact samples: the design lists none (subsection Samples, Contact "
                       "samples), or `softchain reduce` has not written " + file + ".");
        return;
      }
    const auto                            table = data::CsvTable::read(path);
    SvgCurvePlot                          plot("pressure [kPa]", "force on the obstacle |F| [N]");
    std::vector<std::string>              obstacles;
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < table.n_rows(); ++r)
      {
        const std::string &name = table.text(r, "obstacle");
        if (std::find(obstacles.begin(), obstacles.end(), name) == obstacles.end())
          obstacles.push_back(name);
        rows.push_back({name, table.text(r, "shape"), fmt(table.number(r, "pressure") / 1e3),
                        fmt(table.number(r, "force_x")), fmt(table.number(r, "force_y")),
                        fmt(table.number(r, "force_z")), fmt(table.number(r, "force_norm")),
                        fmt(table.number(r, "tip_angle_deg")), table.text(r, "status")});
      }
    for (const auto &name : obstacles)
      {
        SvgCurvePlot::Points points;
        for (std::size_t r = 0; r < table.n_rows(); ++r)
          if (table.text(r, "obstacle") == name && table.text(r, "status") == "converged")
            points.emplace_back(table.number(r, "pressure") / 1e3, table.number(r, "force_norm"));
        plot.add(name, points);
      }
    page.paragraph("The finger inflated against rigid obstacles (subsection Contact; the FEM's "
                   "augmented-Lagrangian contact, docs/contact.md). Against a table under the "
                   "tip the force is the actuator's blocked force; against a cylinder under the "
                   "finger, its grasp force. These samples are not used for the extraction.");
    page.figure(data_uri("image/svg+xml", plot.render("Force on each obstacle against pressure")),
                "From " + file + " (converged samples)");
    page.table({"obstacle", "shape", "pressure [kPa]", "F_x [N]", "F_y [N]", "F_z [N]", "|F| [N]",
                "tip angle [deg]", "status"},
               rows);
    chain_contact(page);
    contact_pictures(page, obstacles);
  }

  // The chains and MuJoCo in contact against the FEM: chain/grasp_summary.csv
  // per model, and per contact sample of chain/validation.csv the force each
  // model's obstacle receives and its error.
  void HtmlReport::chain_contact(HtmlDocument &page) const
  {
    const data::ChainFileSet files(output_directory_);
    if (!fs::exists(files.grasp_summary) || !fs::exists(files.validation))
      {
        page.paragraph("No chain in contact: chain/grasp_summary.csv or chain/validation.csv is missing "
                       "(softchain chain with the role contact among Chain/Validation roles).");
        return;
      }
    const auto summary = data::CsvTable::read(files.grasp_summary);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < summary.n_rows(); ++r)
      rows.push_back({summary.text(r, "model"), summary.text(r, "n_samples"), summary.text(r, "n_failed"),
                      fmt(summary.number(r, "blocked_force_error_percent")),
                      fmt(summary.number(r, "grasp_force_error_percent")),
                      fmt(summary.number(r, "tip_error_percent_L")), fmt(summary.number(r, "orientation_error_deg")),
                      fmt(summary.number(r, "median_solve_time_us"))});
    page.paragraph("The chains in the same scenes (chain/grasp_summary.csv): per model the largest "
                   "absolute error of the force on the obstacle over the blocked-force and over the "
                   "grasp samples, with and without friction, the largest tip errors and the median "
                   "solve time; mujoco is the exported finger in MuJoCo's scenes (simulate/).");
    page.table({"model", "samples", "failed", "blocked force error [%]", "grasp force error [%]",
                "tip error [% L]", "orientation error [deg]", "median solve [µs]"},
               rows);
    const auto validation = data::CsvTable::read(files.validation);
    std::vector<std::string> models, samples;
    const auto               add_once = [](std::vector<std::string> &list, const std::string &key) {
      if (std::find(list.begin(), list.end(), key) == list.end())
        list.push_back(key);
    };
    for (std::size_t r = 0; r < validation.n_rows(); ++r)
      if (std::isfinite(validation.number(r, "fem_contact_force_N")))
        {
          add_once(models, validation.text(r, "model"));
          add_once(samples, validation.text(r, "sample"));
        }
    std::vector<std::string> header{"sample role", "pressure [kPa]", "FEM |F| [N]"};
    for (const auto &m : models)
      for (const std::string what : {" |F| [N]", " error [%]"})
        header.push_back(m + what);
    rows.clear();
    for (const auto &id : samples)
      {
        std::vector<std::string> row;
        for (const auto &m : models)
          for (std::size_t r = 0; r < validation.n_rows(); ++r)
            if (validation.text(r, "sample") == id && validation.text(r, "model") == m)
              {
                if (row.empty())
                  row = {validation.text(r, "role"), fmt(validation.number(r, "pressure") / 1e3),
                         fmt(validation.number(r, "fem_contact_force_N"))};
                row.push_back(fmt(validation.number(r, "contact_force_N")));
                row.push_back(fmt(validation.number(r, "contact_force_error_percent")));
              }
        row.resize(header.size(), "–");
        rows.push_back(row);
      }
    page.table(header, rows);
  }

  // The finger against each obstacle, at the highest converged pressure of
  // its contact samples, the obstacle drawn behind it.
  void HtmlReport::contact_pictures(HtmlDocument &page, const std::vector<std::string> &obstacles) const
  {
    const SurfaceMesh surface(mesh_);
    Eigen::AlignedBox3d around;
    for (const auto &X : mesh_.X)
      around.extend(Eigen::Vector3d(X[0], X[1], X[2]));
    for (const auto &name : obstacles)
      {
        const data::SampleRecord *shown = nullptr;
        for (const auto &s : samples_)
          if (s.converged() && !s.actuation.obstacles.empty() && s.actuation.obstacles.front().name == name &&
              (!shown || s.actuation.pressure > shown->actuation.pressure))
            shown = &s;
        if (!shown)
          continue;
        std::vector<Outline> backdrop;
        for (const auto &o : shown->actuation.obstacles)
          for (auto &piece : obstacle_outline(o, around))
            backdrop.push_back(std::move(piece));
        SvgFingerRenderer renderer(surface, mesh_.X);
        renderer.include(shown->x);
        renderer.include(backdrop);
        const std::string title = name + " at " + fmt(shown->actuation.pressure / 1e3) + " kPa";
        page.figure(data_uri("image/svg+xml", renderer.render(shown->x, title, {}, backdrop)),
                    "sample " + shown->id + ": the finger on the obstacle '" + name + "'");
      }
  }

  void HtmlReport::timing_section(HtmlDocument &page) const
  {
    page.heading("7. Run times");
    if (stage_times_)
      {
        std::vector<std::vector<std::string>> rows;
        for (const auto &stage : *stage_times_)
          rows.push_back({stage.name, fmt(stage.seconds)});
        page.table({"stage of softchain run", "wall time [s]"}, rows);
      }
    else
      page.paragraph("Stage times: not measured in this run (`softchain report` rebuilt the report "
                     "from existing outputs; `softchain run` measures them).");
    // By role, then load, as the .prm lists them.
    std::vector<const data::SampleRecord *> sorted;
    for (const auto &s : samples_)
      sorted.push_back(&s);
    std::sort(sorted.begin(), sorted.end(), [](const auto *a, const auto *b) {
      return std::make_tuple(a->actuation.role, a->actuation.pressure, largest_force(a->actuation)) <
             std::make_tuple(b->actuation.role, b->actuation.pressure, largest_force(b->actuation));
    });
    std::vector<std::vector<std::string>> rows;
    double                                total = 0;
    for (const auto *sample : sorted)
      {
        const data::SampleRecord &s = *sample;
        total += s.wall_time;
        rows.push_back({s.id, s.actuation.role, fmt(s.actuation.pressure / 1e3),
                        fmt(largest_force(s.actuation)), data::status_name(s.status), s.reason, std::to_string(s.load_steps),
                        std::to_string(s.newton_iterations), fmt(s.wall_time)});
      }
    page.paragraph("FEM samples in the database (wall time of the solve that stored each; " +
                   fmt(total) + " s in all):");
    page.table({"sample", "role", "pressure [kPa]", "largest |force| [N]", "status", "reason", "load steps",
                "Newton iterations", "wall time [s]"},
               rows);
  }

  void HtmlReport::claims_section(HtmlDocument &page) const
  {
    page.heading("8. The paper's claims (Sec. IV-A, V)");
    int extraction = 0;
    for (const auto &s : samples_)
      extraction += s.converged() && s.actuation.role != "validation" && s.actuation.obstacles.empty();
    const PaperClaims claims({design_.name, output_directory_, data::method_name(chain_.method),
                              chain_.half_width_fraction, extraction});
    std::ostringstream html;
    html << "<table>\n<tr><th>#</th><th>claim and criterion</th><th>verdict</th><th>measured</th></tr>\n";
    for (const auto &c : claims.claims())
      html << "<tr><td>" << c.number << "</td><td style=\"text-align:left\">"
           << HtmlDocument::escape(c.statement) << "</td><td class=\""
           << (c.verdict == Verdict::holds ? "holds" : c.verdict == Verdict::does_not_hold ? "fails" : "unknown")
           << "\">" << verdict_text(c.verdict) << "</td><td style=\"text-align:left\">"
           << HtmlDocument::escape(c.measured) << "</td></tr>\n";
    html << "</table>\n";
    page.raw(html.str());
  }

  std::string HtmlReport::html() const
  {
    HtmlDocument page("SoftChain report: " + design_.name);
    summary_section(page);
    design_section(page);
    finger_section(page);
    stiffness_section(page);
    validation_section(page);
    protocol_section(page);
    contact_section(page);
    timing_section(page);
    claims_section(page);
    return page.str();
  }
} // namespace softchain::report
