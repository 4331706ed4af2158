#include <softchain/data/design_parameters.h>

namespace softchain::data
{
  std::string DesignParameters::database_path() const
  {
    return output_directory + "/database.h5";
  }

  void DesignParameters::declare(PrmSection &section)
  {
    section.declare("Name", "demo_bender",
                    "Design name: names the output directory and the database.");
    section.declare("Output directory", "", "Where outputs go; empty: output/<Name>.");
  }

  DesignParameters DesignParameters::parse(const PrmSection &section)
  {
    DesignParameters p;
    p.name = section.get("Name");
    section.require(!p.name.empty(), "Name", "must not be empty");
    p.output_directory = section.get("Output directory");
    if (p.output_directory.empty())
      p.output_directory = "output/" + p.name;
    return p;
  }

  DesignParameters DesignParameters::read(const PrmFile &file)
  {
    PrmSection section;
    declare(section);
    file.parse_section("Design", section);
    return parse(section);
  }
} // namespace softchain::data
