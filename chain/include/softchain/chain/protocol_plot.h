#pragma once
// ProtocolPlot: the base torques Tx, Ty, Tz over the validation protocol's
// trace (protocol_torques.csv), one panel each, in the style of the paper's
// Figs. 10-11: the FEM (ground truth) in black, each chain model in colour,
// the beam-theory baseline dashed. Drawn by gnuplot when it is installed;
// the script is written either way.
#include <string>
#include <vector>

namespace softchain::chain
{
  class ProtocolPlot
  {
  public:
    ProtocolPlot(std::string directory, std::vector<std::string> models);

    std::string script() const;
    // Writes <directory>/protocol_torques.gp and, with gnuplot,
    // protocol_torques.png; returns whether the PNG was drawn.
    bool draw() const;

  private:
    std::string              directory_;
    std::vector<std::string> models_;
  };
} // namespace softchain::chain
