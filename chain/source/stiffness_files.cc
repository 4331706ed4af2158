#include <softchain/chain/joint_tables.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/warn_once.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace softchain::chain
{
  namespace
  {
    using data::CsvTable;
    using data::InputError;
    using data::warn_once;

    // The k column of each axis: 0 psi (torsion), 1 theta (lateral), 2 phi.
    const std::array<std::string, 3> k_columns_of_axis = {"k_psi", "k_theta", "k_phi"};

    std::string where(const std::string &path, std::size_t row)
    {
      return path + ", row " + std::to_string(row + 1) + ": ";
    }

    CsvTable read_table(const std::string &path, const std::vector<std::string> &columns)
    {
      if (!std::filesystem::exists(path))
        throw InputError("missing chain input file '" + path + "' (run the reduction first)");
      CsvTable table = CsvTable::read(path);
      for (const std::string &c : columns)
        if (!table.has_column(c))
          throw InputError(path + ": missing column '" + c + "'");
      if (table.n_rows() == 0)
        throw InputError(path + ": no rows");
      return table;
    }

    // Joint number of a row as a 0-based index; must be one of 1..n.
    int joint_index(const CsvTable &table, const std::string &path, std::size_t row, int n)
    {
      const double joint = table.number(row, "joint");
      if (!(joint >= 1 && joint <= n && joint == std::round(joint)))
        throw InputError(where(path, row) + "joint " + table.text(row, "joint") +
                         " is not one of the joints 1.." + std::to_string(n));
      return static_cast<int>(joint) - 1;
    }

    std::string number_text(const double v)
    {
      std::ostringstream text;
      text << v;
      return text.str();
    }

    // A usable stiffness is positive and finite. NaN (no usable sample) and
    // k <= 0 (e.g. a pressure torque opposite to the bending at a joint near
    // the base, or too few samples) are not: the caller holds such a joint
    // rigid or reports it.
    bool usable(const double k)
    {
      return std::isfinite(k) && k > 0.0;
    }

    // NaN or a finite number; an infinite k is an input error.
    double stiffness_entry(const CsvTable &table, const std::string &path, std::size_t row,
                           const std::string &column)
    {
      const double k = table.number(row, column);
      if (std::isinf(k))
        throw InputError(where(path, row) + column + " = " + table.text(row, column) +
                         " is not a finite stiffness");
      return k;
    }

    double finite_number(const CsvTable &table, const std::string &path, std::size_t row,
                         const std::string &column)
    {
      const double v = table.number(row, column);
      if (!std::isfinite(v))
        throw InputError(where(path, row) + column + " = " + table.text(row, column) +
                         " is not a finite number");
      return v;
    }

    // Tabulated (pressure, value) pairs of one quantity, as PiecewiseLinear.
    PiecewiseLinear in_pressure(const std::map<double, double> &table, const std::string &path,
                                const std::string &what)
    {
      if (table.empty())
        throw InputError(path + ": no value of " + what);
      std::vector<double> pressures, values;
      for (const auto &[p, v] : table)
        {
          pressures.push_back(p);
          values.push_back(v);
        }
      return PiecewiseLinear(pressures, values);
    }

    // A second row for the same pressure (e.g. a pressure sample at p = 0
    // beside the rest row) must repeat the value up to round-off.
    void insert_consistent(std::map<double, double> &table, double pressure, double value,
                           const std::string &path, std::size_t row)
    {
      const auto [at, inserted] = table.emplace(pressure, value);
      if (!inserted && std::abs(at->second - value) > 1e-9 * std::max(std::abs(value), std::abs(at->second)))
        throw InputError(where(path, row) + "joint listed twice at the same pressure with different values");
    }

    // "3 joints (2: -2.3, 4: -1.85, 5: -5.8)": a warning's count and items.
    std::string counted(const std::vector<std::string> &items, const std::string &noun)
    {
      std::string text = std::to_string(items.size()) + " " + noun + (items.size() == 1 ? "" : "s") + " (";
      for (std::size_t k = 0; k < items.size(); ++k)
        text += (k ? ", " : "") + items[k];
      return text + ")";
    }

    struct StiffnessTable
    {
      std::vector<Eigen::Vector3d> joint_centres;
      std::vector<Eigen::Vector3d> twist_points; // S_i; J_i without the S columns
      std::vector<Eigen::Vector3d> stiffness;
      // Per axis, the joints held rigid for want of a usable value, with
      // that value ("joint: value"); warned about where the chain uses them.
      std::array<std::map<int, std::string>, 3> held;
      std::vector<std::string>                  k_columns; // the columns read, k_psi[_fit], ...
    };

    // The warning for the joints of `axis` that the chain holds rigid.
    void warn_held_rigid(const std::string &path, const std::string &column,
                         const std::map<int, std::string> &held)
    {
      if (held.empty())
        return;
      std::vector<std::string> items;
      for (const auto &[joint, item] : held)
        items.push_back(item);
      warn_once("chain: warning: " + path + ": " + column + " is not a positive stiffness at " +
                  counted(items, "joint") +
                  "; held rigid about this axis (nan: no sample turned the joint by the "
                  "rotation threshold; negative: it turned against its torque, carried by "
                  "its neighbours or through another axis, as theta with psi on an "
                  "inflated finger)",
                std::cerr);
    }

    // A joint axis without a usable stiffness (NaN: no usable sample, e.g. a
    // joint in the solid base fill that transmits no pressure torque; or
    // k <= 0) is held rigid, k = 1e6 x the largest stiffness of that axis,
    // with a warning. An axis that no sample loaded (no value at any joint,
    // e.g. torsion in a pressure-only sample set) is held rigid at every
    // joint, k = 1e6 x the largest stiffness of any axis: the chain then
    // bends about the loaded axes only. No usable value at all is an error.
    // The joints held rigid are recorded in `held`, not yet warned about: a
    // table in pressure may give them a stiffness (read_model).
    void hold_rigid_where_missing(std::vector<Eigen::Vector3d> &stiffness, const std::string &path,
                                  const std::vector<std::string> &columns, const bool rigid,
                                  std::array<std::map<int, std::string>, 3> &held)
    {
      Eigen::Vector3d rigid_k;
      const auto largest_of = [&](const int axis) {
        double largest = 0;
        for (const auto &k : stiffness)
          if (usable(k[axis]))
            largest = std::max(largest, k[axis]);
        return largest;
      };
      const double largest_any = std::max({largest_of(0), largest_of(1), largest_of(2)});
      if (largest_any == 0)
        throw InputError(path + ": no positive stiffness at any joint and axis (the reduction had "
                                "no usable sample)");
      for (int axis = 0; axis < 3; ++axis)
        {
          const double largest = largest_of(axis);
          rigid_k[axis]        = 1e6 * (largest > 0 ? largest : largest_any);
          if (largest == 0)
            {
              if (!rigid)
                throw InputError(path + ": " + columns[axis] +
                                 " has no positive value at any joint (no sample loads this "
                                 "axis; Chain/Missing stiffness = rigid holds it rigid)");
              warn_once("chain: warning: " + path + ": no " + columns[axis] +
                          " at any joint (no sample loads this axis); the chain is held rigid about it",
                        std::cerr);
            }
          for (std::size_t joint = 0; joint < stiffness.size(); ++joint)
            if (!usable(stiffness[joint][axis]))
              {
                const std::string what = columns[axis] + " = " + number_text(stiffness[joint][axis]);
                if (!rigid)
                  throw InputError(where(path, joint) + what +
                                   " is not a positive finite stiffness (no usable sample, or "
                                   "a torque opposite to the rotation; Chain/Missing stiffness = "
                                   "rigid holds such joints rigid)");
                if (largest > 0)
                  held[axis][static_cast<int>(joint)] =
                    std::to_string(joint + 1) + ": " + number_text(stiffness[joint][axis]);
                stiffness[joint][axis] = rigid_k[axis];
              }
        }
    }

    StiffnessTable read_stiffness(const std::string &path, const StiffnessColumn column,
                                  const bool rigid_where_missing)
    {
      const std::string suffix = column == StiffnessColumn::fit ? "_fit" : "";
      const std::vector<std::string> k_columns = {"k_psi" + suffix, "k_theta" + suffix,
                                                  "k_phi" + suffix};
      const CsvTable table = read_table(path, {"joint", "Jx", "Jy", "Jz", k_columns[0],
                                               k_columns[1], k_columns[2]});
      StiffnessTable result;
      const int      n = static_cast<int>(table.n_rows());
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          if (joint_index(table, path, row, n) != static_cast<int>(row))
            throw InputError(where(path, row) + "expected joint " + std::to_string(row + 1) +
                             ", found " + table.text(row, "joint") +
                             " (joints must be listed 1..n without gaps)");
          result.joint_centres.emplace_back(finite_number(table, path, row, "Jx"),
                                            finite_number(table, path, row, "Jy"),
                                            finite_number(table, path, row, "Jz"));
          if (row > 0 && !(result.joint_centres[row].x() > result.joint_centres[row - 1].x()))
            throw InputError(where(path, row) + "Jx must increase from joint to joint");
          result.twist_points.push_back(result.joint_centres.back());
          if (table.has_column("Sx") && table.has_column("Sy") && table.has_column("Sz"))
            {
              result.twist_points.back() = {finite_number(table, path, row, "Sx"),
                                            finite_number(table, path, row, "Sy"),
                                            finite_number(table, path, row, "Sz")};
              if (result.twist_points.back().x() != result.joint_centres.back().x())
                throw InputError(where(path, row) + "Sx must equal Jx (the twist axis passes through "
                                                    "the joint's section)");
            }
          Eigen::Vector3d k;
          for (int axis = 0; axis < 3; ++axis)
            k[axis] = stiffness_entry(table, path, row, k_columns[axis]);
          result.stiffness.push_back(k);
        }
      hold_rigid_where_missing(result.stiffness, path, k_columns, rigid_where_missing, result.held);
      result.k_columns = k_columns;
      return result;
    }

    // k(p) about `axis` per joint from the usable values of the table's k
    // column (see usable()); a joint without any keeps `fallback` (its k
    // from the stiffness table, rigid if that was not usable either). A
    // non-positive value is skipped with a warning when `rigid`, else an
    // input error. `n_pressures` returns the number of distinct pressures.
    std::vector<PiecewiseLinear> read_k_in_pressure(const std::string &path, int n, int axis,
                                                    const std::vector<Eigen::Vector3d> &fallback,
                                                    const bool rigid, std::size_t &n_pressures,
                                                    std::vector<bool> &uses_fallback)
    {
      const std::string column = k_columns_of_axis[axis];
      const CsvTable    table  = read_table(path, {"pressure", "joint", column});
      std::vector<std::map<double, double>> per_joint(n);
      std::set<double>                      pressures;
      std::vector<std::string>              skipped; // "line: value" of the rows left out
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          const int    joint = joint_index(table, path, row, n);
          const double k     = stiffness_entry(table, path, row, column);
          pressures.insert(finite_number(table, path, row, "pressure"));
          if (std::isnan(k))
            continue; // no value at this pressure (rotation below threshold)
          if (!usable(k))
            {
              if (!rigid)
                throw InputError(where(path, row) + column + " = " + table.text(row, column) +
                                 " is not a positive finite stiffness");
              skipped.push_back(std::to_string(row + 1) + ": " + table.text(row, column));
              continue;
            }
          insert_consistent(per_joint[joint], finite_number(table, path, row, "pressure"), k,
                            path, row);
        }
      if (!skipped.empty())
        warn_once("chain: warning: " + path + ": " + column + " is not positive in " +
                    counted(skipped, "row") +
                    "; skipped (the joint turned against its torque at that pressure, carried "
                    "by its neighbours or through another axis)",
                  std::cerr);
      n_pressures = pressures.size();
      std::vector<PiecewiseLinear> result;
      uses_fallback.assign(n, false);
      for (int i = 0; i < n; ++i)
        {
          uses_fallback[i] = per_joint[i].empty();
          result.push_back(uses_fallback[i] ?
                             PiecewiseLinear({0.0}, {fallback[i][axis]}) :
                             in_pressure(per_joint[i], path, column + " for joint " + std::to_string(i + 1)));
        }
      return result;
    }

    // The joints' force laws (FabricHinge per joint and pressure): springs
    // and fibre stiffness positive (kappa may be 0), pre-stretch not negative.
    JointForceLaw read_force_law(const std::string &path, int n)
    {
      const std::vector<std::string> columns = {"pressure", "joint", "k_psi", "k_theta", "k_phi",
                                                "kappa", "r", "theta_0"};
      const CsvTable table = read_table(path, columns);
      std::vector<std::map<double, data::FabricHinge>> per_joint(n);
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          data::FabricHinge hinge;
          for (int a = 0; a < 3; ++a)
            hinge.k[a] = finite_number(table, path, row, k_columns_of_axis[a]);
          hinge.kappa   = finite_number(table, path, row, "kappa");
          hinge.r       = finite_number(table, path, row, "r");
          hinge.theta_0 = finite_number(table, path, row, "theta_0");
          hinge.layer_give = table.has_column("layer_give") ? finite_number(table, path, row, "layer_give") : 0.0;
          if (!(hinge.k.minCoeff() > 0) || hinge.kappa < 0 || hinge.theta_0 < 0 || hinge.layer_give < 0)
            throw InputError(where(path, row) + "k_psi, k_theta and k_phi must be positive, kappa, "
                                                "theta_0 and layer_give not negative");
          const int joint = joint_index(table, path, row, n);
          if (!per_joint[joint].emplace(finite_number(table, path, row, "pressure"), hinge).second)
            throw InputError(where(path, row) + "pressure " + table.text(row, "pressure") +
                             " listed twice for joint " + table.text(row, "joint"));
        }
      std::vector<JointForceLaw::Table> tables(n);
      for (int i = 0; i < n; ++i)
        for (const auto &[pressure, hinge] : per_joint[i])
          {
            tables[i].pressures.push_back(pressure);
            tables[i].hinges.push_back(hinge);
          }
      return JointForceLaw(std::move(tables));
    }

    std::vector<PiecewiseLinear> read_pressure_torque(const std::string &path, int n)
    {
      const std::vector<std::string> components = {"jp_x", "jp_y", "jp_z"};
      const CsvTable table = read_table(path, {"pressure", "joint", "jp_x", "jp_y", "jp_z"});
      std::vector<std::map<double, double>> per_angle(3 * n);
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          const int    joint    = joint_index(table, path, row, n);
          const double pressure = finite_number(table, path, row, "pressure");
          for (int c = 0; c < 3; ++c)
            insert_consistent(per_angle[3 * joint + c], pressure,
                        finite_number(table, path, row, components[c]), path, row);
        }
      for (int j = 0; j < 3 * n; ++j)
        if (per_angle[j].count(0.0) == 0)
          throw InputError(path + ": no rest row (pressure 0) for joint " + std::to_string(j / 3 + 1));
      std::vector<PiecewiseLinear> result;
      for (int j = 0; j < 3 * n; ++j)
        result.push_back(in_pressure(per_angle[j], path, components[j % 3]));
      return result;
    }

    // Every point of the link geometry (the joints, then the tip) at every
    // tabulated pressure, each beyond the one before along x. That keeps
    // them in order at every pressure between (a convex combination of
    // increasing sequences increases), as KinematicChain requires.
    void check_link_order(const std::vector<std::array<std::map<double, double>, 3>> &per_point,
                          const std::string                                           &path)
    {
      const auto name = [&](const std::size_t i) {
        return i + 1 < per_point.size() ? "joint " + std::to_string(i + 1) : std::string("the tip");
      };
      std::set<double> pressures;
      for (const auto &point : per_point)
        for (const auto &[pressure, x] : point[0])
          pressures.insert(pressure);
      for (const double pressure : pressures)
        for (std::size_t i = 0; i < per_point.size(); ++i)
          {
            if (per_point[i][0].count(pressure) == 0)
              throw InputError(path + ": no row for " + name(i) + " at pressure " + number_text(pressure));
            if (i > 0 && !(per_point[i][0].at(pressure) > per_point[i - 1][0].at(pressure)))
              throw InputError(path + ": at pressure " + number_text(pressure) + ", " + name(i) +
                               " does not lie beyond " + name(i - 1) + " along x");
          }
    }

    // The link geometry U_i(p), U_T(p), Q_T(p) (LinkGeometry): per pressure
    // a row for each joint (point 1..n) and the tip (point "tip", its
    // rx, ry, rz the tip frame's rotation vector); the rest rows (pressure 0)
    // must be the chain's reference joints and tip, with no tip rotation.
    LinkGeometry read_link_geometry(const std::string &path, const std::vector<Eigen::Vector3d> &joints,
                                    const Eigen::Vector3d &tip)
    {
      const int      n     = static_cast<int>(joints.size());
      const CsvTable table = read_table(path, {"pressure", "point", "x", "y", "z", "rx", "ry", "rz"});
      std::vector<std::array<std::map<double, double>, 3>> per_point(n + 1);
      std::array<std::map<double, double>, 3>              tip_frame;
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          const std::string point = table.text(row, "point");
          int               index = n;
          if (point != "tip")
            {
              const double joint = table.number(row, "point");
              if (!(joint >= 1 && joint <= n && joint == std::round(joint)))
                throw InputError(where(path, row) + "point " + point + " is neither one of the joints 1.." +
                                 std::to_string(n) + " nor 'tip'");
              index = static_cast<int>(joint) - 1;
            }
          const double pressure = finite_number(table, path, row, "pressure");
          for (int c = 0; c < 3; ++c)
            insert_consistent(per_point[index][c], pressure,
                              finite_number(table, path, row, std::string(1, char('x' + c))), path, row);
          if (index == n)
            for (int c = 0; c < 3; ++c)
              insert_consistent(tip_frame[c], pressure,
                                finite_number(table, path, row, "r" + std::string(1, char('x' + c))), path, row);
        }
      for (int c = 0; c < 3; ++c)
        if (tip_frame[c].count(0.0) > 0 && std::abs(tip_frame[c].at(0.0)) > 1e-9)
          throw InputError(path + ": the rest row of the tip has a tip frame rotation (" +
                           number_text(tip_frame[c].at(0.0)) + " rad); at rest it is 0 (to 1e-9 rad)");
      std::vector<LinkGeometry::PointInPressure> points;
      for (int i = 0; i <= n; ++i)
        {
          const std::string     name      = i < n ? "joint " + std::to_string(i + 1) : std::string("the tip");
          const Eigen::Vector3d reference = i < n ? joints[i] : tip;
          for (int c = 0; c < 3; ++c)
            {
              const auto rest = per_point[i][c].find(0.0);
              if (rest == per_point[i][c].end())
                throw InputError(path + ": no rest row (pressure 0) for " + name);
              if (std::abs(rest->second - reference(c)) > 1e-9)
                throw InputError(path + ": the rest row of " + name + " (" + number_text(rest->second) +
                                 " m) is not the chain's reference position (" + number_text(reference(c)) +
                                 " m): the files come from different reductions");
            }
          points.push_back({in_pressure(per_point[i][0], path, "x of " + name),
                            in_pressure(per_point[i][1], path, "y of " + name),
                            in_pressure(per_point[i][2], path, "z of " + name)});
        }
      check_link_order(per_point, path);
      const LinkGeometry::PointInPressure tip_table = points.back();
      points.pop_back();
      return LinkGeometry(std::move(points), tip_table,
                          {in_pressure(tip_frame[0], path, "rx of the tip"),
                           in_pressure(tip_frame[1], path, "ry of the tip"),
                           in_pressure(tip_frame[2], path, "rz of the tip")});
    }

    // An optional table: none if the file is missing or has no rows, else
    // with `columns` (an InputError naming the file and the missing column).
    std::optional<CsvTable> optional_table(const std::string &path, const std::vector<std::string> &columns)
    {
      if (!std::filesystem::exists(path))
        return std::nullopt;
      CsvTable table = CsvTable::read(path);
      if (table.n_rows() == 0)
        return std::nullopt;
      for (const std::string &column : columns)
        if (!table.has_column(column))
          throw InputError(path + ": missing column '" + column + "'");
      return table;
    }

    // A compliance in pressure (the links' c(p), LinkCompliance; the
    // sections' c_s(p) and c_t(p), ChainContact's skin and CoulombFriction):
    // one row per pressure, finite and not negative; none if the file is
    // missing or has no rows.
    std::optional<PiecewiseLinear> read_compliance(const std::string &path)
    {
      const auto table = optional_table(path, {"pressure", "compliance"});
      if (!table)
        return std::nullopt;
      std::map<double, double> compliance;
      for (std::size_t row = 0; row < table->n_rows(); ++row)
        {
          const double c = finite_number(*table, path, row, "compliance");
          if (c < 0)
            throw InputError(where(path, row) + "compliance = " + table->text(row, "compliance") +
                             " is negative");
          if (!compliance.emplace(finite_number(*table, path, row, "pressure"), c).second)
            throw InputError(where(path, row) + "pressure " + table->text(row, "pressure") + " listed twice");
        }
      return in_pressure(compliance, path, "compliance");
    }

    // The links' shift per in-plane turn g_i(p) (LinkShiftPerTurn): per
    // pressure a row for each link 1..n, finite; none if the file is missing
    // or has no rows.
    std::optional<LinkShiftPerTurn> read_link_shift(const std::string &path, const int n)
    {
      const auto read = optional_table(path, {"pressure", "link", "shift_x", "shift_y"});
      if (!read)
        return std::nullopt;
      const CsvTable &table = *read;
      std::vector<std::array<std::map<double, double>, 2>> per_link(n);
      for (std::size_t row = 0; row < table.n_rows(); ++row)
        {
          const double link = table.number(row, "link");
          if (!(link >= 1 && link <= n && link == std::round(link)))
            throw InputError(where(path, row) + "link " + table.text(row, "link") + " is not one of 1.." +
                             std::to_string(n));
          const double pressure = finite_number(table, path, row, "pressure");
          for (int c = 0; c < 2; ++c)
            if (!per_link[int(link) - 1][c]
                   .emplace(pressure, finite_number(table, path, row, c == 0 ? "shift_x" : "shift_y"))
                   .second)
              throw InputError(where(path, row) + "link " + table.text(row, "link") + " listed twice at pressure " +
                               table.text(row, "pressure"));
        }
      std::vector<LinkShiftPerTurn::ShiftInPressure> links;
      for (int i = 0; i < n; ++i)
        {
          const std::string name = "link " + std::to_string(i + 1);
          if (per_link[i][0].empty())
            throw InputError(path + ": no row for " + name);
          links.push_back({in_pressure(per_link[i][0], path, "shift_x of " + name),
                           in_pressure(per_link[i][1], path, "shift_y of " + name)});
        }
      return LinkShiftPerTurn(std::move(links));
    }
  } // namespace

  StiffnessFiles::StiffnessFiles(const std::string &stiffness_directory,
                                 const data::RotationMethod method, double half_width_fraction)
  {
    const data::StiffnessFileSet files(stiffness_directory, label(method, half_width_fraction));
    stiffness_path_           = files.table;
    bending_in_pressure_path_ = files.kphi_vs_pressure;
    force_in_pressure_paths_  = {files.kpsi_vs_pressure, files.ktheta_vs_pressure};
    pressure_torque_path_     = files.pressure_torque;
    link_geometry_path_       = files.link_geometry;
    link_shift_path_          = files.link_shift;
    link_compliance_path_     = files.link_compliance;
    skin_compliance_path_     = files.skin_compliance;
    skin_shear_compliance_path_ = files.skin_shear_compliance;
    joint_law_path_           = files.joint_law;
  }

  std::string StiffnessFiles::label(const data::RotationMethod method, double half_width_fraction)
  {
    return data::stiffness_label(method, half_width_fraction);
  }

  bool StiffnessFiles::exist() const { return std::filesystem::exists(stiffness_path_); }

  ChainModel StiffnessFiles::read_model(const std::string &name, const Eigen::Vector3d &tip,
                                        const StiffnessColumn column, bool in_pressure,
                                        bool rigid_where_missing, bool twist_axes) const
  {
    StiffnessTable table = read_stiffness(stiffness_path_, column, rigid_where_missing);
    const int      n     = static_cast<int>(table.stiffness.size());
    if (!(tip.x() > table.joint_centres.back().x()))
      throw InputError(stiffness_path_ + ": the last joint lies beyond the finger's tip");
    JointTables joints;
    joints.joint_centres   = table.joint_centres;
    joints.stiffness       = table.stiffness;
    joints.pressure_torque = read_pressure_torque(pressure_torque_path_, n);
    if (in_pressure)
      {
        std::size_t       n_pressures = 0;
        std::vector<bool> uses_fallback;
        // A joint held rigid in the stiffness table that a table in
        // pressure gives a stiffness is not held rigid: no warning for it.
        const auto covered = [&](const int axis) {
          for (int joint = 0; joint < n; ++joint)
            if (!uses_fallback[joint])
              table.held[axis].erase(joint);
        };
        joints.k_in_pressure[2] = read_k_in_pressure(bending_in_pressure_path_, n, 2, table.stiffness,
                                                     rigid_where_missing, n_pressures, uses_fallback);
        covered(2);
        // k_psi(p), k_theta(p) where the torsion (lateral) samples were made
        // at more than one pressure; otherwise (also without any such
        // sample: a table of no rows) k stays the stiffness table's.
        for (const int axis : {0, 1})
          if (std::filesystem::exists(force_in_pressure_paths_[axis]) &&
              CsvTable::read(force_in_pressure_paths_[axis]).n_rows() > 0)
            {
              auto tables = read_k_in_pressure(force_in_pressure_paths_[axis], n, axis, table.stiffness,
                                               rigid_where_missing, n_pressures, uses_fallback);
              if (n_pressures > 1)
                {
                  joints.k_in_pressure[axis] = std::move(tables);
                  covered(axis);
                }
            }
      }
    for (int axis = 0; axis < 3; ++axis)
      warn_held_rigid(stiffness_path_, table.k_columns[axis], table.held[axis]);
    if (in_pressure && std::filesystem::exists(link_geometry_path_))
      joints.link_geometry = read_link_geometry(link_geometry_path_, table.joint_centres, tip);
    if (in_pressure)
      {
        joints.link_shift      = read_link_shift(link_shift_path_, n);
        joints.link_compliance = read_compliance(link_compliance_path_);
        joints.skin_compliance = read_compliance(skin_compliance_path_);
        joints.skin_shear_compliance = read_compliance(skin_shear_compliance_path_);
      }
    if (in_pressure && std::filesystem::exists(joint_law_path_) && CsvTable::read(joint_law_path_).n_rows() > 0)
      joints.force_law = read_force_law(joint_law_path_, n);
    if (twist_axes)
      joints.twist_points = table.twist_points;
    return joints.model(name, tip, in_pressure);
  }
} // namespace softchain::chain
