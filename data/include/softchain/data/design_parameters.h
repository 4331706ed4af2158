#pragma once
// DesignParameters: "subsection Design" of a .prm -- the design's name and
// where its outputs go. Every command reads it, to find the database.
#include <softchain/data/prm_file.h>

#include <string>

namespace softchain::data
{
  struct DesignParameters
  {
    std::string name;             // names the output directory
    std::string output_directory; // default output/<name>

    // <output directory>/database.h5
    std::string database_path() const;

    static void             declare(PrmSection &section);
    static DesignParameters parse(const PrmSection &section);
    // Declares, fills from `file` and parses subsection Design.
    static DesignParameters read(const PrmFile &file);
  };
} // namespace softchain::data
