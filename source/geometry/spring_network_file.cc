#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/geometry/spring_network_file.h>
#include <softchain/geometry/text_lines.h>

#include <sstream>

namespace softchain::geometry
{
  namespace
  {
    const std::string header = "# SoftChain spring network v1";

    // The next line that is neither blank nor a comment, as a stream.
    bool next_significant(TextLines &lines, std::istringstream &stream)
    {
      for (std::string line; lines.next(line);)
        {
          const auto first = line.find_first_not_of(" \t");
          if (first != std::string::npos && line[first] != '#')
            {
              stream = std::istringstream(line);
              return true;
            }
        }
      return false;
    }

    void read_header(TextLines &lines)
    {
      std::string first;
      if (!lines.next(first) || first.substr(0, first.find_last_not_of(' ') + 1) != header)
        lines.fail("expected the first line '" + header + "'");
    }

    SpringNetwork::Polyline read_polyline(TextLines &lines, std::istringstream &line)
    {
      std::string kind;
      long        n = -1;
      line >> kind >> n;
      if ((kind != "open" && kind != "closed") || n < 0)
        lines.fail("expected 'polyline open|closed N'");
      SpringNetwork::Polyline polyline{kind == "closed", std::vector<Eigen::Vector3d>(n)};
      for (auto &p : polyline.points)
        {
          std::string rest;
          if (!next_significant(lines, line) || !(line >> p.x() >> p.y() >> p.z()) || (line >> rest))
            lines.fail("expected a node 'x y z' (polyline of " + std::to_string(n) + " nodes)");
        }
      return polyline;
    }
  } // namespace

  std::vector<SpringNetwork> SpringNetworkFile::read(const std::string &path)
  {
    TextLines lines(path, "spring network file");
    read_header(lines);
    std::vector<SpringNetwork> networks;
    for (std::istringstream line; next_significant(lines, line);)
      {
        std::string keyword;
        line >> keyword;
        if (keyword == "network")
          {
            networks.push_back({});
            if (!(line >> networks.back().name))
              lines.fail("expected 'network NAME'");
          }
        else if (keyword == "polyline" && !networks.empty())
          networks.back().polylines.push_back(read_polyline(lines, line));
        else
          lines.fail("expected 'network NAME' or 'polyline open|closed N' after a network line");
      }
    return networks;
  }

  std::string SpringNetworkFile::text(const std::vector<SpringNetwork> &networks)
  {
    std::ostringstream out;
    out << header << "\n";
    for (const auto &network : networks)
      {
        out << "network " << network.name << "\n";
        for (const auto &polyline : network.polylines)
          {
            out << "polyline " << (polyline.closed ? "closed " : "open ") << polyline.points.size()
                << "\n";
            for (const auto &p : polyline.points)
              out << data::canonical(p.x()) << " " << data::canonical(p.y()) << " "
                  << data::canonical(p.z()) << "\n";
          }
      }
    return out.str();
  }

  void SpringNetworkFile::write(const std::string &path, const std::vector<SpringNetwork> &networks)
  {
    TextLines::write_all(path, text(networks), "spring network file");
  }
} // namespace softchain::geometry
