// The table of prm_subsections.h. "Finger design" shapes the solution only
// through the mesh and springs it generates, which the design hash covers
// themselves; "Design" names and places the outputs; loads and samples are
// each sample's own part of its id.
#include <softchain/data/prm_subsections.h>

#include <algorithm>

namespace softchain::data
{
  const std::vector<PrmSubsection> &prm_subsections()
  {
    static const std::vector<PrmSubsection> table = {
      {"Design", "data layer (name, output directory)", false},
      {"Mesh", "FEM", true},
      {"Materials", "FEM", true},
      {"Springs", "FEM", true},
      {"Solver", "FEM", true},
      {"Loads", "FEM (softchain solve)", false},
      {"Contact", "geometry (obstacles) and FEM (contact law)", false},
      {"Output", "FEM", false},
      {"Finger design", "geometry", false},
      {"Samples", "FEM sample sweep", false},
      {"Protocol", "FEM sample sweep (the validation protocol)", false},
      {"Reduction", "reduction", false},
      {"Chain", "chain", false}};
    return table;
  }

  bool defines_design(const std::string &title)
  {
    const auto &table = prm_subsections();
    return std::any_of(table.begin(), table.end(), [&](const PrmSubsection &s) {
      return s.title == title && s.defines_design;
    });
  }
} // namespace softchain::data
