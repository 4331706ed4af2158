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

    std::string point(const Eigen::Vector3d &p)
    {
      return data::canonical(p.x()) + " " + data::canonical(p.y()) + " " + data::canonical(p.z());
    }

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

    // 'sheet N M', then N corners 'x y z' and M families 'fibre dx dy dz spacing'.
    FibreSheet read_sheet(TextLines &lines, std::istringstream &line)
    {
      long n = -1, m = -1;
      line >> n >> m;
      if (n < 3 || m < 1)
        lines.fail("expected 'sheet N M' (N >= 3 corners, M >= 1 fibre families)");
      FibreSheet  sheet{std::vector<Eigen::Vector3d>(n), std::vector<FibreSheet::Family>(m)};
      std::string rest, keyword;
      for (auto &p : sheet.corners)
        if (!next_significant(lines, line) || !(line >> p.x() >> p.y() >> p.z()) || (line >> rest))
          lines.fail("expected a corner 'x y z' (sheet of " + std::to_string(n) + " corners)");
      for (auto &f : sheet.families)
        {
          Eigen::Vector3d &a = f.direction;
          if (!next_significant(lines, line) || !(line >> keyword >> a.x() >> a.y() >> a.z() >> f.spacing) ||
              keyword != "fibre" || (line >> rest) || !(f.spacing > 0) || !(a.norm() > 0))
            lines.fail("expected 'fibre dx dy dz spacing' (a nonzero direction, a positive spacing)");
          a.normalize();
        }
      return sheet;
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
        else if (keyword == "sheet" && !networks.empty())
          networks.back().sheets.push_back(read_sheet(lines, line));
        else
          lines.fail("expected 'network NAME', or 'polyline open|closed N' or 'sheet N M' after a "
                     "network line");
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
              out << point(p) << "\n";
          }
        for (const auto &sheet : network.sheets)
          {
            out << "sheet " << sheet.corners.size() << " " << sheet.families.size() << "\n";
            for (const auto &p : sheet.corners)
              out << point(p) << "\n";
            for (const auto &f : sheet.families)
              out << "fibre " << point(f.direction) << " " << data::canonical(f.spacing) << "\n";
          }
      }
    return out.str();
  }

  void SpringNetworkFile::write(const std::string &path, const std::vector<SpringNetwork> &networks)
  {
    TextLines::write_all(path, text(networks), "spring network file");
  }
} // namespace softchain::geometry
