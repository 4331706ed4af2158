#pragma once
// ValidationPlot: PNG of the chain-vs-FEM tip errors per sample and model
// (validation.csv), drawn by gnuplot when it is installed (scripts/setup
// installs gnuplot-nox); the script is written either way.
#include <string>
#include <vector>

namespace softchain::chain
{
  // Writes `script` to `script_path` and runs gnuplot on it if installed;
  // returns whether gnuplot ran and succeeded.
  bool run_gnuplot(const std::string &script_path, const std::string &script);

  class ValidationPlot
  {
  public:
    ValidationPlot(std::string directory, std::vector<std::string> models);

    std::string script() const;
    // Writes <directory>/validation.gp and, with gnuplot, validation.png;
    // returns whether the PNG was drawn.
    bool draw() const;

  private:
    std::string              directory_;
    std::vector<std::string> models_;
  };
} // namespace softchain::chain
