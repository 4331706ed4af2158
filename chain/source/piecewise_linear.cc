#include <softchain/chain/piecewise_linear.h>

#include <algorithm>
#include <stdexcept>

namespace softchain::chain
{
  PiecewiseLinear::PiecewiseLinear(std::vector<double> abscissae, std::vector<double> values)
    : abscissae_(std::move(abscissae))
    , values_(std::move(values))
  {
    if (abscissae_.empty() || abscissae_.size() != values_.size())
      throw std::invalid_argument("PiecewiseLinear: need as many values as abscissae, at least one");
    for (std::size_t i = 1; i < abscissae_.size(); ++i)
      if (!(abscissae_[i] > abscissae_[i - 1]))
        throw std::invalid_argument("PiecewiseLinear: abscissae must increase strictly");
  }

  double PiecewiseLinear::operator()(double x) const
  {
    if (x <= abscissae_.front())
      return values_.front();
    if (x >= abscissae_.back())
      return values_.back();
    const auto   upper = std::upper_bound(abscissae_.begin(), abscissae_.end(), x);
    const auto   i     = static_cast<std::size_t>(upper - abscissae_.begin());
    const double t     = (x - abscissae_[i - 1]) / (abscissae_[i] - abscissae_[i - 1]);
    return (1.0 - t) * values_[i - 1] + t * values_[i];
  }

  void merge_abscissae(const std::vector<double> &abscissae, std::vector<double> &merged)
  {
    merged.insert(merged.end(), abscissae.begin(), abscissae.end());
    std::sort(merged.begin(), merged.end());
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
  }

  void merge_abscissae(const std::vector<PiecewiseLinear> &tables, std::vector<double> &merged)
  {
    for (const PiecewiseLinear &table : tables)
      merge_abscissae(table.abscissae(), merged);
  }
} // namespace softchain::chain
