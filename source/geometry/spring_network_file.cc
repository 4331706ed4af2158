#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/geometry/spring_network_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace softchain::geometry
{
  namespace
  {
    const std::string header = "# SoftChain spring network v1";

    // Reader of the significant lines (not blank, not comments), with numbers.
    class SignificantLines
    {
    public:
      explicit SignificantLines(const std::string &path)
        : in_(path)
        , path_(path)
      {
        if (!in_)
          throw data::InputError(path + ": cannot open the spring network file");
        std::string first;
        std::getline(in_, first);
        number_ = 1;
        if (first.substr(0, first.find_last_not_of(" \r") + 1) != header)
          fail("expected the first line '" + header + "'");
      }

      bool next(std::istringstream &line)
      {
        for (std::string text; std::getline(in_, text);)
          {
            ++number_;
            const auto first = text.find_first_not_of(" \t\r");
            if (first == std::string::npos || text[first] == '#')
              continue;
            line = std::istringstream(text);
            return true;
          }
        return false;
      }

      [[noreturn]] void fail(const std::string &what) const
      {
        throw data::InputError(path_ + ":" + std::to_string(number_) + ": " + what);
      }

    private:
      std::ifstream in_;
      std::string   path_;
      int           number_ = 0;
    };

    SpringNetwork::Polyline read_polyline(SignificantLines &lines, std::istringstream &line)
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
          if (!lines.next(line) || !(line >> p.x() >> p.y() >> p.z()) || (line >> rest))
            lines.fail("expected a node 'x y z' (polyline of " + std::to_string(n) + " nodes)");
        }
      return polyline;
    }
  } // namespace

  std::vector<SpringNetwork> SpringNetworkFile::read(const std::string &path)
  {
    SignificantLines           lines(path);
    std::vector<SpringNetwork> networks;
    for (std::istringstream line; lines.next(line);)
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
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(path);
    out << text(networks);
    if (!out)
      throw data::InputError(path + ": cannot write the spring network file");
  }
} // namespace softchain::geometry
