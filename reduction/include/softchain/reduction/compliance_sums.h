#pragma once
// ComplianceSums: the non-negative least-squares compliance of deflections
// r_s = c F_s over the samples s at one pressure (LinkComplianceFit,
// SkinComplianceFit),
//   c = max(0, sum_s r_s F_s / sum_s F_s^2):
// a body does not give against the force, so a negative value (what the
// frames resolve of a stiff body, or a deflection the model does not hold)
// becomes 0 with a warning.
#include <softchain/data/csv_table.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::reduction
{
  struct ComplianceSums
  {
    double deflection_force = 0.0; // sum_s r_s . F_s, m N
    double force_squared    = 0.0; // sum_s |F_s|^2, N^2
    int    samples          = 0;

    void add(const double r_dot_F, const double F_squared)
    {
      deflection_force += r_dot_F;
      force_squared += F_squared;
      ++samples;
    }

    // c, or nothing if the samples carry no force. A negative c appends
    // `negative` and the least-squares value to `warnings`.
    std::optional<double> compliance(const std::string &negative, std::vector<std::string> &warnings) const
    {
      if (!(force_squared > 0.0))
        return std::nullopt;
      const double c = deflection_force / force_squared;
      if (c >= 0.0)
        return c;
      warnings.push_back(negative + " (least squares value " + data::CsvTable::cell(c) + " m/N)");
      return 0.0;
    }
  };
} // namespace softchain::reduction
