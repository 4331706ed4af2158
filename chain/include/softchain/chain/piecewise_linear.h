#pragma once
// PiecewiseLinear: a scalar tabulated against pressure (the reduction's
// k_phi(p) and J_p(p) tables), interpolated linearly between the tabulated
// pressures and held constant beyond the first and last one (no extrapolation
// of a secant stiffness outside the sampled range).
#include <vector>

namespace softchain::chain
{
  class PiecewiseLinear
  {
  public:
    // Abscissae strictly increasing, same count as values, at least one;
    // throws std::invalid_argument otherwise.
    PiecewiseLinear(std::vector<double> abscissae, std::vector<double> values);

    double operator()(double x) const;
    const std::vector<double> &abscissae() const { return abscissae_; }
    const std::vector<double> &values() const { return values_; }

  private:
    std::vector<double> abscissae_;
    std::vector<double> values_;
  };

  // Adds `abscissae` to `merged`, kept sorted and unique.
  void merge_abscissae(const std::vector<double> &abscissae, std::vector<double> &merged);
  // Adds the abscissae of `tables` to `merged`: the points between which all
  // of them (and whatever `merged` held) are linear.
  void merge_abscissae(const std::vector<PiecewiseLinear> &tables, std::vector<double> &merged);
} // namespace softchain::chain
