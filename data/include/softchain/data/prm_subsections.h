#pragma once
// The top-level subsections of a SoftChain .prm file: which tier declares
// their entries, and whether they define the design -- change the FEM's
// solution for the same loads, and so enter the design hash that keys the
// database's cache. This table is the one place that says so; PrmFile
// rejects any other top-level subsection.
#include <string>
#include <vector>

namespace softchain::data
{
  struct PrmSubsection
  {
    std::string title;
    std::string owner;          // the tier that declares its entries
    bool        defines_design; // enters the design hash
  };

  const std::vector<PrmSubsection> &prm_subsections();

  // True if `title` is a subsection of prm_subsections() that defines the design.
  bool defines_design(const std::string &title);
} // namespace softchain::data
