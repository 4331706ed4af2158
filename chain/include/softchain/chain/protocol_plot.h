#pragma once
// The protocol's plot: the base torques Tx, Ty, Tz over the validation
// protocol's trace (protocol_torques.csv), one panel each, in the style of
// the paper's Figs. 10-11: the FEM (ground truth) in black, each chain model
// in colour, the beam-theory baseline dashed.
#include <string>
#include <vector>

namespace softchain::chain
{
  // The gnuplot script for <directory>/protocol_torques.csv and `models`.
  std::string protocol_plot_script(const std::string &directory, const std::vector<std::string> &models);
  // Writes <directory>/protocol_torques.gp and, with gnuplot installed,
  // protocol_torques.png; returns whether the PNG was drawn.
  bool draw_protocol_plot(const std::string &directory, const std::vector<std::string> &models);
} // namespace softchain::chain
