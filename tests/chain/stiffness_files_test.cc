// Reading the reduction's CSVs into a chain, and the errors for bad files.
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "../data/stream_redirect.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>
#include <iostream>

#include "../data/occurrences.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace softchain::chain;
namespace data = softchain::data;
using softchain::chain::testing::UniformReduction;
using softchain::data::InputError;

namespace
{
  const Eigen::Vector3d tip(0.09, 0.0, 0.0);

  // The uniform reduction's files (M2, b = a/2) in a scratch directory.
  struct UniformFiles
  {
    explicit UniformFiles(const std::string &name)
      : dir(name)
      , files(dir.path().string(), data::RotationMethod::affine_fit, 0.5)
    {
      testing::write_reduction(files, r);
    }
    softchain::testing::ScratchDirectory dir;
    StiffnessFiles                       files;
    UniformReduction                     r;
  };

  // Rewrites the file `path` with `edit` applied to its text.
  template <typename Edit>
  void rewrite_file(const std::string &path, Edit edit)
  {
    std::string text;
    {
      std::ifstream in(path);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    edit(text);
    std::ofstream(path) << text;
  }

  // Replaces the stiffness file by the uniform table with `edit` applied to its text.
  template <typename Edit>
  void rewrite_stiffness(const StiffnessFiles &files, Edit edit)
  {
    rewrite_file(files.stiffness_path(), edit);
  }

  // Sets field `column` (0-based) of the row of CSV file `path` that starts
  // with `key` + ",".
  void set_row_field(const std::string &path, const std::string &key, int column,
                     const std::string &value)
  {
    rewrite_file(path, [&](std::string &text) {
      std::istringstream lines(text);
      std::string        line, result;
      while (std::getline(lines, line))
        {
          if (line.rfind(key + ",", 0) == 0)
            {
              std::size_t start = 0;
              for (int c = 0; c < column; ++c)
                start = line.find(',', start) + 1;
              const std::size_t end = line.find(',', start);
              line.replace(start, (end == std::string::npos ? line.size() : end) - start, value);
            }
          result += line + "\n";
        }
      text = result;
    });
  }

  void replace(std::string &text, const std::string &from, const std::string &to)
  {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  }
} // namespace

TEST_CASE("the file label is the method and b as a fraction of a with two decimals")
{
  CHECK(StiffnessFiles::label(data::RotationMethod::affine_fit, 0.5) == "M2_b0.50a");
  CHECK(StiffnessFiles::label(data::RotationMethod::bounding_box, 1.0 / 3.0) == "M1_b0.33a");
  const StiffnessFiles files("out/stiffness", data::RotationMethod::bounding_box, 1.0);
  CHECK(files.pressure_torque_path() == "out/stiffness/M1_b1.00a_pressure_torque.csv");
}

TEST_CASE("a joint without a stiffness (NaN) is held rigid about that axis")
{
  // E.g. P10's joint 1 lies in the solid base fill: the whole closed cavity
  // is distal to it, so the pressure transmits no torque and the reduction
  // writes no k_phi there.
  const UniformFiles      uniform("chain_rigid_joint");
  const StiffnessFiles   &files = uniform.files;
  const UniformReduction &r     = uniform.r;
  // Joint 1: k_phi (8th column) nan in the stiffness table, and no k_phi(p).
  set_row_field(files.stiffness_path(), "1", 7, "nan");
  for (const char *pressure : {"40000", "80000"})
    set_row_field(files.bending_in_pressure_path(), std::string(pressure) + ",1", 2, "nan");
  for (const bool in_pressure : {false, true})
    {
      const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, in_pressure);
      INFO("k_phi interpolated in pressure: " << in_pressure);
      // Rigid: 1e6 x the largest k_phi of the table; joint 2 as written.
      // With Chain/Missing stiffness = error it is an error naming the row.
      try
        {
          files.read_model("M2", tip, StiffnessColumn::value, in_pressure, false);
          FAIL("no error");
        }
      catch (const InputError &e)
        {
          CHECK_THAT(e.what(), Catch::Contains(files.stiffness_path() + ", row 1") &&
                                 Catch::Contains("k_phi = nan"));
        }
      CHECK(model.stiffness().diagonal(r.p_max)[2] == Approx(1e6 * r.k[2]).epsilon(1e-12));
      CHECK(model.stiffness().diagonal(r.p_max)[5] ==
            Approx(r.k[2] * (in_pressure ? 1 - r.k_phi_drop : 1)).epsilon(1e-12));
    }
}

TEST_CASE("a joint with a negative stiffness is held rigid like one without")
{
  // E.g. P10 reduced from only 5 and 10 kPa: at joint 2, next to the base
  // fill, the pressure torque about the bounding-box centre opposes the
  // bending and the reduction writes k_phi < 0.
  const UniformFiles      uniform("chain_negative_joint");
  const StiffnessFiles   &files = uniform.files;
  const UniformReduction &r     = uniform.r;
  set_row_field(files.stiffness_path(), "1", 7, "-0.02");
  for (const char *pressure : {"40000", "80000"})
    set_row_field(files.bending_in_pressure_path(), std::string(pressure) + ",1", 2, "-0.02");
  // Joint 2: negative at 40 kPa only, so its k_phi(p) keeps the 80 kPa value.
  set_row_field(files.bending_in_pressure_path(), "40000,2", 2, "-0.01");
  // Read twice (as `softchain run`'s stages do): each cause warned once,
  // with its count and values.
  std::ostringstream warnings;
  const ChainModel   model = [&] {
    const softchain::testing::StreamRedirect to(std::cerr, warnings);
    files.read_model("M2", tip, StiffnessColumn::value, true);
    return files.read_model("M2", tip, StiffnessColumn::value, true);
  }();
  CHECK(softchain::testing::occurrences(warnings.str(), "\n") == 2);
  CHECK(warnings.str().find(files.stiffness_path() + ": k_phi is not a positive stiffness at 1 joint (1: -0.02)") !=
        std::string::npos);
  CHECK(warnings.str().find(files.bending_in_pressure_path() + ": k_phi is not positive in 3 rows (") !=
        std::string::npos);
  CHECK(model.stiffness().diagonal(r.p_max)[2] == Approx(1e6 * r.k[2]).epsilon(1e-12));
  CHECK(model.stiffness().diagonal(0.0)[5] == Approx((1 - r.k_phi_drop) * r.k[2]).epsilon(1e-12));
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true, false),
                    Catch::Contains(files.stiffness_path() + ", row 1") &&
                      Catch::Contains("k_phi = -0.02"));
}

TEST_CASE("a joint that its table in pressure gives a stiffness is not warned about as held rigid")
{
  // E.g. P10's k_psi at joint 7 from the largest torsion sample (50 kPa,
  // the finger curled past 120 degrees) is negative, while its k_psi(p) from
  // the lightest sample per pressure is positive: the chain uses the table.
  const UniformFiles      uniform("chain_table_covers_joint");
  const StiffnessFiles   &files = uniform.files;
  const UniformReduction &r     = uniform.r;
  set_row_field(files.stiffness_path(), "2", 7, "-0.03");
  std::ostringstream warnings;
  const softchain::testing::StreamRedirect to(std::cerr, warnings);
  const ChainModel   in_pressure = files.read_model("M2", tip, StiffnessColumn::value, true);
  CHECK(warnings.str().find("is not a positive stiffness") == std::string::npos);
  // Without the tables in pressure the stiffness table's value is used, and
  // the joint is held rigid with the warning.
  const ChainModel at_rest = files.read_model("M2", tip, StiffnessColumn::value, false);
  CHECK(warnings.str().find(files.stiffness_path() + ": k_phi is not a positive stiffness at 1 joint (2: -0.03)") !=
        std::string::npos);
  CHECK(in_pressure.stiffness().diagonal(r.p_max)[5] < 1e3 * r.k[2]);
  CHECK(at_rest.stiffness().diagonal(r.p_max)[5] == Approx(1e6 * r.k[2]).epsilon(1e-12));
}

TEST_CASE("the reduction's files give joints, stiffness and pressure tables")
{
  softchain::testing::ScratchDirectory dir("chain_stiffness_files");
  const StiffnessFiles                 files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  const UniformReduction               r;
  testing::write_reduction(files, r);
  REQUIRE(files.exist());

  SECTION("value column, constant in pressure")
  {
    const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, false);
    CHECK(model.chain().n_joints() == r.n);
    CHECK(model.chain().joint_centre(3).x() == Approx(3.5 * r.a));
    CHECK(model.stiffness().diagonal(r.p_max).segment<3>(6) == r.k);
    CHECK(model.actuation().torque(r.p_max).segment<3>(6) == r.jp * r.p_max);
  }
  SECTION("fit column, k_phi and J_p interpolated in pressure")
  {
    const ChainModel model = files.read_model("M2", tip, StiffnessColumn::fit, true);
    CHECK(model.stiffness().diagonal(0.0)[0] == r.k_fit[0]);
    // Halfway between the rows at p_max / 2 and p_max: linear interpolation,
    // exact up to round-off.
    const double p = 0.75 * r.p_max;
    CHECK(model.stiffness().diagonal(p)[5] == Approx((1 - r.k_phi_drop * 0.75) * r.k[2]).epsilon(1e-14));
    CHECK(model.actuation().torque(p)[5] == Approx((1 + r.jp_growth * 0.75) * r.jp[2] * p).epsilon(1e-14));
    // Below the first pressure with a k_phi value it is held constant.
    CHECK(model.stiffness().diagonal(0.0)[2] == Approx((1 - r.k_phi_drop * 0.5) * r.k[2]).epsilon(1e-14));
  }
}

TEST_CASE("bad stiffness files are input errors naming file and row")
{
  softchain::testing::ScratchDirectory dir("chain_bad_stiffness");
  const StiffnessFiles                 files(dir.path().string(), data::RotationMethod::bounding_box, 1.0);
  testing::write_reduction(files, UniformReduction{});
  const auto error_of = [&](const StiffnessColumn column) {
    try
      {
        files.read_model("M1", tip, column, true);
      }
    catch (const InputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  const std::string path = files.stiffness_path();

  SECTION("a missing joint")
  {
    rewrite_stiffness(files, [](std::string &t) { replace(t, "\n3,", "\n4,"); });
    CHECK_THAT(error_of(StiffnessColumn::value), Catch::Contains(path + ", row 3") && Catch::Contains("expected joint 3"));
  }
  SECTION("a negative stiffness: an error with Missing stiffness = error, else rigid")
  {
    set_row_field(path, "1", 6, "-0.05"); // joint 1, k_theta
    try
      {
        files.read_model("M1", tip, StiffnessColumn::value, true, false);
        FAIL("no error");
      }
    catch (const InputError &e)
      {
        CHECK_THAT(e.what(), Catch::Contains(path + ", row 1") && Catch::Contains("k_theta = -0.05"));
      }
    CHECK(error_of(StiffnessColumn::value) == "no error");
  }
  SECTION("an infinite stiffness")
  {
    UniformReduction r;
    r.k[0] = INFINITY;
    testing::stiffness_table(r).write(path);
    CHECK_THAT(error_of(StiffnessColumn::value), Catch::Contains(path + ", row 1") && Catch::Contains("not a finite stiffness"));
  }
  SECTION("no stiffness about an axis at any joint: rigid about it, or an error")
  {
    // E.g. a pressure-only sample set: no sample twists the finger.
    UniformReduction r;
    r.k_fit[0] = NAN;
    testing::stiffness_table(r).write(path);
    const ChainModel model = files.read_model("M1", tip, StiffnessColumn::fit, false);
    // 1e6 x the largest fit stiffness of any axis (k_theta_fit = 0.06).
    for (int joint = 0; joint < r.n; ++joint)
      CHECK(model.stiffness().diagonal(0.0)[3 * joint] == Approx(1e6 * 0.06).epsilon(1e-12));
    CHECK(model.stiffness().diagonal(0.0)[1] == Approx(r.k_fit[1]).epsilon(1e-12));
    CHECK_THROWS_WITH(files.read_model("M1", tip, StiffnessColumn::fit, false, false),
                      Catch::Contains(path) && Catch::Contains("k_psi_fit has no positive value at any joint"));
  }
  SECTION("no stiffness at all")
  {
    UniformReduction r;
    r.k = Eigen::Vector3d(NAN, -1.0, NAN);
    testing::stiffness_table(r).write(path);
    CHECK_THAT(error_of(StiffnessColumn::value), Catch::Contains(path) && Catch::Contains("no positive stiffness at any joint and axis"));
  }
  SECTION("a missing column")
  {
    rewrite_stiffness(files, [](std::string &t) { replace(t, "k_phi_fit", "kphi_fit"); });
    CHECK_THAT(error_of(StiffnessColumn::fit), Catch::Contains(path) && Catch::Contains("missing column 'k_phi_fit'"));
    CHECK(error_of(StiffnessColumn::value) == "no error"); // the value columns are all there
  }
  SECTION("a pressure listed twice for a joint: same value accepted, different value not")
  {
    std::ofstream(files.pressure_torque_path(), std::ios::app) << "0,2,0,0,2e-07\n";
    CHECK(error_of(StiffnessColumn::value) == "no error");
    std::ofstream(files.pressure_torque_path(), std::ios::app) << "0,2,0,0,3e-07\n";
    CHECK_THAT(error_of(StiffnessColumn::value), Catch::Contains(files.pressure_torque_path() + ", row 29") &&
                                    Catch::Contains("twice"));
  }
  SECTION("a missing pressure torque file")
  {
    std::filesystem::remove(files.pressure_torque_path());
    CHECK_THAT(error_of(StiffnessColumn::value), Catch::Contains(files.pressure_torque_path()));
  }
}

TEST_CASE("k_theta and k_psi follow their pressure tables only when these hold several pressures")
{
  softchain::testing::ScratchDirectory dir("chain_force_in_pressure");
  const StiffnessFiles                 files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  const UniformReduction               r;
  testing::write_reduction(files, r);
  // k at p = 0 is 2x the stiffness table's, 4x at p_max: the chain must
  // take the table's values, and interpolate linearly between them.
  const auto write_table = [&](int axis, const std::vector<double> &pressures) {
    softchain::data::CsvTable table({"pressure", "joint", axis == 0 ? "k_psi" : "k_theta"});
    for (const double p : pressures)
      for (int i = 0; i < r.n; ++i)
        table.add_row(std::vector<double>{p, double(i + 1), (2 + 2 * p / r.p_max) * r.k[axis]});
    table.write(files.force_in_pressure_path(axis));
  };
  for (const int axis : {0, 1})
    {
      INFO("axis " << axis);
      write_table(axis, {}); // no sample loads the axis: no rows, the stiffness table stands
      CHECK(files.read_model("M2", tip, StiffnessColumn::value, true).stiffness().diagonal(0)[axis] ==
            Approx(r.k[axis]).epsilon(1e-15));
      write_table(axis, {0.0}); // one pressure: no k(p), the stiffness table stands
      CHECK(files.read_model("M2", tip, StiffnessColumn::value, true).stiffness().diagonal(0)[axis] ==
            Approx(r.k[axis]).epsilon(1e-15));
      write_table(axis, {0.0, r.p_max});
      const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, true);
      for (int i = 0; i < r.n; ++i)
        {
          CHECK(model.stiffness().diagonal(0)[3 * i + axis] == Approx(2 * r.k[axis]).epsilon(1e-15));
          CHECK(model.stiffness().diagonal(0.5 * r.p_max)[3 * i + axis] ==
                Approx(3 * r.k[axis]).epsilon(1e-15));
        }
      // Without interpolation in pressure the tables are not read.
      CHECK(files.read_model("M2", tip, StiffnessColumn::value, false).stiffness().diagonal(r.p_max)[axis] ==
            Approx(r.k[axis]).epsilon(1e-15));
      std::filesystem::remove(files.force_in_pressure_path(axis));
    }
}
