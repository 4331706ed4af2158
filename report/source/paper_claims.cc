#include <softchain/chain/stiffness_files.h>
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/output_files.h>
#include <softchain/report/report_numbers.h>
#include <softchain/report/paper_claims.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <tuple>

namespace softchain::report
{
  namespace
  {
    // The paper states its claims about the affine-fit method's tables.
    constexpr data::RotationMethod M2 = data::RotationMethod::affine_fit;

    // Height (y extent) of the mesh nodes within 2 % of the length from the
    // base face and from the tip face.
    std::pair<double, double> end_heights(const data::MeshRecord &mesh)
    {
      double x_min = INFINITY, x_max = -INFINITY;
      for (const auto &X : mesh.X)
        x_min = std::min(x_min, X[0]), x_max = std::max(x_max, X[0]);
      const double band = 0.02 * (x_max - x_min);
      double       base[2] = {INFINITY, -INFINITY}, tip[2] = {INFINITY, -INFINITY};
      for (const auto &X : mesh.X)
        for (double *end : {X[0] <= x_min + band ? base : nullptr, X[0] >= x_max - band ? tip : nullptr})
          if (end)
            end[0] = std::min(end[0], X[1]), end[1] = std::max(end[1], X[1]);
      return {base[1] - base[0], tip[1] - tip[0]};
    }

    namespace fs = std::filesystem;

    // Rotations below the reduction's default threshold (0.1 degree) give
    // no stiffness there (reduction/README.md): not used here either.
    constexpr double rotation_threshold = 0.1 * M_PI / 180;
    // Lateral forces above this buckle the finger (the paper, Sec. IV-A).
    constexpr double buckling_force = 0.7; // N
    // A per-sample k_theta "departs" when it differs from its median over
    // the forces up to buckling by more than this fraction.
    constexpr double departure = 0.2;


    // A fraction in percent, without exponents: 240 %, 4.8 %.
    std::string percent(const double fraction)
    {
      std::ostringstream text;
      text.setf(std::ios::fixed);
      text.precision(std::abs(fraction) >= 0.1 ? 0 : 1);
      text << 100 * fraction << " %";
      return text.str();
    }

    // The finite values of one column of a stiffness table, joint by joint.
    struct Series
    {
      std::vector<int>    joint;
      std::vector<double> x, value;
    };

    Series read_series(const std::string &path, const std::string &column)
    {
      const auto table = data::CsvTable::read(path);
      Series     series;
      for (std::size_t r = 0; r < table.n_rows(); ++r)
        if (std::isfinite(table.number(r, column)))
          {
            series.joint.push_back(static_cast<int>(table.number(r, "joint")));
            series.x.push_back(table.number(r, "x_ref"));
            series.value.push_back(table.number(r, column));
          }
      return series;
    }

    double mean(const std::vector<double> &v)
    {
      double sum = 0;
      for (const double x : v)
        sum += x;
      return v.empty() ? NAN : sum / v.size();
    }


    // Least-squares slope of y over x.
    double slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double mx = mean(x), my = mean(y);
      double       sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          sxy += (x[i] - mx) * (y[i] - my);
          sxx += (x[i] - mx) * (x[i] - mx);
        }
      return sxy / sxx;
    }

    std::string joined(const std::vector<double> &v, const std::string &separator = ", ")
    {
      std::string text;
      for (std::size_t i = 0; i < v.size(); ++i)
        text += (i ? separator : "") + fmt(v[i]);
      return text;
    }

    Claim claim(const std::string &number, const std::string &statement, const Verdict verdict,
                const std::string &measured)
    {
      return {number, statement, verdict, measured};
    }

    // "no FILE: run parameter_files/<design>.prm to measure"
    std::string missing(const std::string &file, const std::string &design)
    {
      return "no " + file + ": run parameter_files/" + design + ".prm to measure";
    }

    // Per joint, the lateral samples' (force, theta, k_theta = tau_y / theta)
    // at p = 0 (the paper's) sorted by force, from a <label>_samples.csv.
    struct LateralPoint
    {
      double force, theta, k;
    };
    std::map<int, std::vector<LateralPoint>> lateral_points(const std::string &path)
    {
      const auto                               table = data::CsvTable::read(path);
      std::map<int, std::vector<LateralPoint>> points;
      for (std::size_t r = 0; r < table.n_rows(); ++r)
        if (table.text(r, "role") == "lateral" && table.number(r, "pressure") == 0)
          {
            const double theta = table.number(r, "theta");
            points[static_cast<int>(table.number(r, "joint"))].push_back(
              {table.number(r, "force_norm"), theta, table.number(r, "tau_y") / theta});
          }
      for (auto &[joint, list] : points)
        std::sort(list.begin(), list.end(),
                  [](const LateralPoint &a, const LateralPoint &b) { return a.force < b.force; });
      return points;
    }

    // Median k_theta over the points with force in (low, high] whose
    // rotation is above the threshold.
    double median_k(const std::vector<LateralPoint> &points, const double low, const double high)
    {
      std::vector<double> k;
      for (const auto &p : points)
        if (p.force > low && p.force <= high && std::abs(p.theta) >= rotation_threshold)
          k.push_back(p.k);
      return median(k);
    }
  } // namespace

  std::string verdict_text(const Verdict verdict)
  {
    return verdict == Verdict::holds         ? "holds" :
           verdict == Verdict::does_not_hold ? "does not hold" :
                                               "not measurable here";
  }

  PaperClaims::PaperClaims(const ClaimInputs &inputs)
    : in_(inputs)
  {
    claims_ = {constant_for_regular_shape(), thicker_walls_stiffer(), decreases_along_taper(),
               decreases_with_pressure(),    m1_more_sensitive_to_b(), lateral_fails_past_buckling(),
               lateral_unreliable_small(),   kpsi_higher_near_base(),  few_samples_suffice()};
  }

  std::string PaperClaims::stiffness_directory(const std::string &design) const
  {
    const fs::path own(in_.output_directory);
    return ((design == in_.design_name ? own : own.parent_path() / design) / data::folder::stiffness).string();
  }

  std::string PaperClaims::label(const data::RotationMethod method) const
  {
    return chain::StiffnessFiles::label(method, in_.half_width_fraction);
  }

  Claim PaperClaims::constant_for_regular_shape() const
  {
    const std::string statement =
      "k_φ is constant along a regular finger (parallelepiped, M2). Criterion: the joints "
      "between the one next to the base and the tip one lie within ±15 % of their mean.";
    const std::string file = data::StiffnessFileSet(stiffness_directory("parallelepiped"), label(M2)).table;
    if (!fs::exists(file))
      return claim("1a", statement, Verdict::not_measurable, missing(file, "parallelepiped"));
    const Series s = read_series(file, "k_phi");
    if (s.value.size() < 4)
      return claim("1a", statement, Verdict::not_measurable, "fewer than 4 joints with a k_φ in " + file);
    // The joints next to the clamped base and under the tip cap are
    // stiffened by them; the claim is about the regular part in between.
    const std::vector<double> inside(s.value.begin() + 1, s.value.end() - 1);
    const auto [low, high] = std::minmax_element(inside.begin(), inside.end());
    const double m = mean(inside), spread = (*high - *low) / (2 * std::abs(m));
    return claim("1a", statement, m > 0 && spread <= 0.15 ? Verdict::holds : Verdict::does_not_hold,
                 "joints " + std::to_string(s.joint[1]) + "–" + std::to_string(s.joint[s.joint.size() - 2]) +
                   ": " + fmt(*low) + " to " + fmt(*high) + " N m/rad (mean " + fmt(m) + ", ±" +
                   percent(spread) + "); next to the base " + fmt(s.value.front()) + ", at the tip " +
                   fmt(s.value.back()));
  }

  Claim PaperClaims::thicker_walls_stiffer() const
  {
    const std::string statement = "k_φ is higher for thicker walls: P13 (6 mm walls) ≈ 2 × P10 "
                                  "(2.5 mm). Criterion: mean k_φ of P13 / P10 (M2) between 1.5 and 3.";
    std::map<std::string, double> means;
    for (const std::string design : {"p10", "p13"})
      {
        const std::string file = data::StiffnessFileSet(stiffness_directory(design), label(M2)).table;
        if (!fs::exists(file))
          return claim("1b", statement, Verdict::not_measurable, missing(file, design));
        means[design] = mean(read_series(file, "k_phi").value);
      }
    const std::string values = "mean k_φ P10 " + fmt(means["p10"]) + ", P13 " + fmt(means["p13"]) + " N m/rad";
    if (!(means["p10"] > 0 && means["p13"] > 0))
      return claim("1b", statement, Verdict::not_measurable,
                   values + ": a k_φ ≤ 0 is not a stiffness. The pressure torque is taken about the "
                            "joint centre (the slab's bounding-box centre); when the cavity lies below "
                            "that centre, as in P13's thick section, the pressure moment has the sign "
                            "opposite to the bending that the fabric drives.");
    const double ratio = means["p13"] / means["p10"];
    return claim("1b", statement, ratio >= 1.5 && ratio <= 3 ? Verdict::holds : Verdict::does_not_hold,
                 values + ": ratio " + fmt(ratio));
  }

  Claim PaperClaims::decreases_along_taper() const
  {
    const std::string statement =
      "k_φ decreases along a tapered finger (M2). Criterion: negative least-squares slope of "
      "k_φ over x, leaving out the joint next to the base (stiffened by the clamp).";
    const std::string file = data::StiffnessFileSet(stiffness_directory(in_.design_name), label(M2)).table;
    if (!fs::exists(file))
      return claim("2a", statement, Verdict::not_measurable, "no " + file);
    const Series k = read_series(file, "k_phi");
    if (k.value.size() < 3)
      return claim("2a", statement, Verdict::not_measurable, "fewer than 3 joints with a k_φ in " + file);
    const std::vector<double> x(k.x.begin() + 1, k.x.end()), v(k.value.begin() + 1, k.value.end());
    const double change = slope(x, v) * (x.back() - x.front()) / mean(v);
    const std::string measured = "joints " + std::to_string(k.joint[1]) + "–" +
                                 std::to_string(k.joint.back()) + ": " + joined(v) +
                                 " N m/rad; trend over them " + percent(change) + " of the mean";
    // The finger's height at its base and at its tip, from the database's
    // mesh (the joints may all sit on the strain-limiting layer, at one
    // height). Within 10 % the finger counts as untapered.
    const std::string database = in_.output_directory + "/database.h5";
    if (!fs::exists(database))
      return claim("2a", statement, Verdict::not_measurable, "no " + database);
    const auto [h0, h1] = end_heights(data::ActuationDatabase::open(database).mesh());
    if (std::abs(h1 - h0) <= 0.1 * std::abs(h0))
      return claim("2a", statement, Verdict::not_measurable,
                   "this finger is not tapered (height " + fmt(1e3 * h0) + " → " +
                     fmt(1e3 * h1) + " mm); " + measured);
    return claim("2a", statement, change < 0 ? Verdict::holds : Verdict::does_not_hold, measured);
  }

  Claim PaperClaims::decreases_with_pressure() const
  {
    const std::string statement =
      "k_φ decreases with pressure. Criterion: the mean k_φ over the joints (M2) is lower at "
      "the highest pressure than at the lowest.";
    const std::string file =
      data::StiffnessFileSet(stiffness_directory(in_.design_name), label(M2)).kphi_vs_pressure;
    if (!fs::exists(file))
      return claim("2b", statement, Verdict::not_measurable, "no " + file);
    const auto                    table = data::CsvTable::read(file);
    std::map<double, std::vector<double>> per_pressure;
    for (std::size_t r = 0; r < table.n_rows(); ++r)
      if (std::isfinite(table.number(r, "k_phi")))
        per_pressure[table.number(r, "pressure")].push_back(table.number(r, "k_phi"));
    if (per_pressure.size() < 2)
      return claim("2b", statement, Verdict::not_measurable, "fewer than 2 pressures with a k_φ in " + file);
    std::vector<double> means;
    for (const auto &[p, k] : per_pressure)
      means.push_back(mean(k));
    return claim("2b", statement, means.back() < means.front() ? Verdict::holds : Verdict::does_not_hold,
                 "mean k_φ " + joined(means, " → ") + " N m/rad from " +
                   fmt(per_pressure.begin()->first / 1e3) + " to " +
                   fmt(per_pressure.rbegin()->first / 1e3) + " kPa" +
                   (means.back() < means.front() ? "" :
                                                   ": J_p grows with pressure faster than the "
                                                   "bending (the walls balloon)"));
  }

  Claim PaperClaims::m1_more_sensitive_to_b() const
  {
    const std::string statement =
      "M1 is more sensitive to the slab half-width b than M2. Criterion: the spread of the "
      "mean k_φ over the b values, relative to their mean magnitude, is larger for M1.";
    // method -> b/a -> mean k_phi, from every <M>_b<f>a.csv of this design.
    std::map<std::string, std::map<double, double>> means;
    const std::regex name("(M[12])_b([0-9.]+)a\\.csv");
    const std::string directory = stiffness_directory(in_.design_name);
    if (fs::is_directory(directory))
      for (const auto &entry : fs::directory_iterator(directory))
        {
          std::smatch match;
          const std::string file = entry.path().filename().string();
          if (std::regex_match(file, match, name))
            means[match[1]][std::stod(match[2])] = mean(read_series(entry.path().string(), "k_phi").value);
        }
    if (means["M1"].size() < 2 || means["M2"].size() < 2)
      return claim("3", statement, Verdict::not_measurable,
                   "needs M1 and M2 tables for at least two b in " + directory);
    std::map<std::string, double> spread;
    std::string                   measured;
    for (const auto &[method, by_b] : means)
      {
        std::vector<double> values, magnitudes, b;
        for (const auto &[fraction, m] : by_b)
          {
            b.push_back(fraction);
            values.push_back(m);
            magnitudes.push_back(std::abs(m));
          }
        const auto [low, high] = std::minmax_element(values.begin(), values.end());
        spread[method] = (*high - *low) / mean(magnitudes);
        measured += method + " mean k_φ " + joined(values, " / ") + " N m/rad for b/a = " +
                    joined(b, " / ") + " (spread " + percent(spread[method]) + "); ";
      }
    return claim("3", statement, spread["M1"] > spread["M2"] ? Verdict::holds : Verdict::does_not_hold,
                 measured.substr(0, measured.size() - 2));
  }

  Claim PaperClaims::lateral_fails_past_buckling() const
  {
    const std::string statement =
      "Lateral (k_θ) extraction fails past buckling, above 0.7 N. Criterion: past 0.7 N the "
      "per-sample k_θ = τ_y/θ of some joint departs by more than 20 % from its median up to "
      "0.7 N, or |θ| decreases as the force grows (M2).";
    const std::string file = data::StiffnessFileSet(stiffness_directory(in_.design_name), label(M2)).samples;
    if (!fs::exists(file))
      return claim("4a", statement, Verdict::not_measurable, "no " + file);
    int    worst_joint = 0;
    double worst = 0, worst_reference = NAN, worst_k = NAN, largest_force = 0;
    std::vector<int> turning_back;
    for (const auto &[joint, points] : lateral_points(file))
      {
        const double reference = median_k(points, 0, buckling_force);
        for (std::size_t i = 0; i < points.size(); ++i)
          {
            largest_force = std::max(largest_force, points[i].force);
            if (points[i].force <= buckling_force)
              continue;
            if (i > 0 && std::abs(points[i].theta) < std::abs(points[i - 1].theta) &&
                (turning_back.empty() || turning_back.back() != joint))
              turning_back.push_back(joint);
            const double d = std::abs(points[i].k / reference - 1);
            if (std::isfinite(d) && d > worst)
              std::tie(worst, worst_joint, worst_reference, worst_k) =
                std::make_tuple(d, joint, reference, points[i].k);
          }
      }
    if (largest_force <= buckling_force)
      return claim("4a", statement, Verdict::not_measurable,
                   "the largest lateral force is " + fmt(largest_force) + " N ≤ 0.7 N");
    std::string measured = "largest departure at joint " + std::to_string(worst_joint) + ": k_θ " +
                           fmt(worst_reference) + " N m/rad up to 0.7 N, " + fmt(worst_k) +
                           " above (" + percent(worst) + ")";
    if (!turning_back.empty())
      {
        measured += "; |θ| decreases with the force past 0.7 N at joint";
        for (const int j : turning_back)
          measured += " " + std::to_string(j);
      }
    return claim("4a", statement,
                 worst > departure || !turning_back.empty() ? Verdict::holds : Verdict::does_not_hold,
                 measured);
  }

  Claim PaperClaims::lateral_unreliable_small() const
  {
    const std::string statement =
      "Lateral (k_θ) extraction is unreliable for small forces. Criterion: at the smallest "
      "lateral force the per-sample k_θ of some joint departs by more than 20 % from its "
      "median over the larger forces up to 0.7 N (M2).";
    const std::string file = data::StiffnessFileSet(stiffness_directory(in_.design_name), label(M2)).samples;
    if (!fs::exists(file))
      return claim("4b", statement, Verdict::not_measurable, "no " + file);
    const auto points = lateral_points(file);
    double     worst = 0, smallest = INFINITY;
    int        worst_joint = 0, below_threshold = 0, compared = 0;
    for (const auto &[joint, list] : points)
      smallest = std::min(smallest, list.front().force);
    for (const auto &[joint, list] : points)
      {
        const double reference = median_k(list, smallest, buckling_force);
        if (list.front().force != smallest || !std::isfinite(reference))
          continue;
        if (std::abs(list.front().theta) < rotation_threshold)
          {
            ++below_threshold;
            continue;
          }
        ++compared;
        const double d = std::abs(list.front().k / reference - 1);
        if (d > worst)
          std::tie(worst, worst_joint) = std::make_pair(d, joint);
      }
    if (compared == 0)
      return claim("4b", statement, Verdict::not_measurable,
                   "needs lateral samples at two or more forces up to 0.7 N with rotations above "
                   "0.1° in " + file);
    return claim("4b", statement, worst > departure ? Verdict::holds : Verdict::does_not_hold,
                 "at " + fmt(smallest) + " N the largest departure is " + percent(worst) + " (joint " +
                   std::to_string(worst_joint) + ", " + std::to_string(compared) + " joints compared; " +
                   std::to_string(below_threshold) + " with θ below 0.1°)");
  }

  Claim PaperClaims::kpsi_higher_near_base() const
  {
    const std::string statement =
      "k_ψ (torsion) is higher near the base. Criterion: the mean k_ψ of the first third of "
      "the joints exceeds that of the last third (M2).";
    const std::string file = data::StiffnessFileSet(stiffness_directory(in_.design_name), label(M2)).table;
    if (!fs::exists(file))
      return claim("5", statement, Verdict::not_measurable, "no " + file);
    const Series s = read_series(file, "k_psi");
    const std::size_t third = s.value.size() / 3;
    if (third == 0)
      return claim("5", statement, Verdict::not_measurable, "fewer than 3 joints with a k_ψ in " + file);
    const double base = mean({s.value.begin(), s.value.begin() + third});
    const double tip  = mean({s.value.end() - third, s.value.end()});
    return claim("5", statement, base > tip ? Verdict::holds : Verdict::does_not_hold,
                 "k_ψ from base to tip " + joined(s.value) + " N m/rad; first " + std::to_string(third) +
                   " joints " + fmt(base) + ", last " + std::to_string(third) + " " + fmt(tip) +
                   " (ratio " + fmt(base / tip) + ")");
  }

  Claim PaperClaims::few_samples_suffice() const
  {
    const std::string statement =
      "Fewer than 30 FEM samples suffice for a good chain. Criterion (ours): the chain's mean "
      "tip position error on the validation samples is at most 5 % of the finger's length.";
    const std::string file = data::ChainFileSet(in_.output_directory).validation_summary;
    if (!fs::exists(file))
      return claim("6", statement, Verdict::not_measurable, "no " + file);
    const auto table = data::CsvTable::read(file);
    // The held-out validation samples when there are any, else all.
    auto row = [&](const std::string &model) -> long {
      long all = -1;
      for (std::size_t r = 0; r < table.n_rows(); ++r)
        if (table.text(r, "model") == model && table.text(r, "roles") == "validation")
          return r;
        else if (table.text(r, "model") == model && table.text(r, "roles") == "all")
          all = r;
      return all;
    };
    const long chain = row(in_.chain_method), baseline = row("baseline");
    if (chain < 0)
      return claim("6", statement, Verdict::not_measurable, "no " + in_.chain_method + " row in " + file);
    const double error = table.number(chain, "mean_tip_error_percent_L");
    std::string  measured =
      std::to_string(in_.extraction_samples) + " converged extraction samples; " + in_.chain_method +
      " chain on the " + table.text(chain, "roles") + " samples: mean tip error " + fmt(error) +
      " % of L (max " + fmt(table.number(chain, "max_tip_error_percent_L")) + " %), max orientation error " +
      fmt(table.number(chain, "max_orientation_error_deg")) + "°";
    if (baseline >= 0)
      measured += "; beam-theory baseline " + fmt(table.number(baseline, "mean_tip_error_percent_L")) + " %";
    if (in_.extraction_samples >= 30)
      return claim("6", statement, Verdict::not_measurable, "this design used 30 or more: " + measured);
    return claim("6", statement, error <= 5 ? Verdict::holds : Verdict::does_not_hold, measured);
  }
} // namespace softchain::report
