#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/geometry/stl_file.h>
#include <softchain/geometry/text_lines.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace softchain::geometry
{
  namespace
  {
    // Binary STL: 80-byte header, uint32 count, 50 bytes per facet (normal,
    // three vertices as float32, uint16 attribute).
    bool is_binary(const std::string &bytes)
    {
      if (bytes.size() < 84)
        return false;
      std::uint32_t n = 0;
      std::memcpy(&n, bytes.data() + 80, 4);
      return bytes.size() == 84 + 50 * std::size_t(n);
    }

    std::vector<StlFile::Triangle> binary_triangles(const std::string &bytes)
    {
      std::vector<StlFile::Triangle> triangles((bytes.size() - 84) / 50);
      for (std::size_t f = 0; f < triangles.size(); ++f)
        for (int v = 0; v < 3; ++v)
          for (int c = 0; c < 3; ++c)
            {
              float value = 0;
              std::memcpy(&value, bytes.data() + 84 + 50 * f + 12 * (v + 1) + 4 * c, 4);
              triangles[f][v][c] = value;
            }
      return triangles;
    }

    std::vector<StlFile::Triangle> ascii_triangles(const std::string &bytes, const std::string &path)
    {
      std::vector<Eigen::Vector3d> vertices;
      std::istringstream           in(bytes);
      for (std::string word; in >> word;)
        if (word == "vertex")
          {
            Eigen::Vector3d v;
            if (!(in >> v.x() >> v.y() >> v.z()))
              throw data::InputError(path + ": malformed 'vertex' line in the STL file");
            vertices.push_back(v);
          }
      if (vertices.empty() || vertices.size() % 3 != 0)
        throw data::InputError(path + ": not an STL file (no facets, or a facet without 3 vertices)");
      std::vector<StlFile::Triangle> triangles;
      for (std::size_t i = 0; i < vertices.size(); i += 3)
        triangles.push_back({vertices[i], vertices[i + 1], vertices[i + 2]});
      return triangles;
    }

    std::array<StlFile::Triangle, 4> split(const StlFile::Triangle &t)
    {
      const Eigen::Vector3d m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]),
                            m20 = 0.5 * (t[2] + t[0]);
      return {{{t[0], m01, m20}, {m01, t[1], m12}, {m20, m12, t[2]}, {m01, m12, m20}}};
    }
  } // namespace

  StlFile StlFile::read(const std::string &path)
  {
    const std::string bytes = TextLines::read_all(path, "STL file");
    StlFile           stl;
    stl.triangles = is_binary(bytes) ? binary_triangles(bytes) : ascii_triangles(bytes, path);
    return stl;
  }

  std::string StlFile::ascii_text() const
  {
    std::ostringstream out;
    out << "solid softchain\n";
    for (const auto &t : triangles)
      {
        out << "facet normal 0 0 0\nouter loop\n";
        for (const auto &v : t)
          out << "vertex " << data::canonical(v.x()) << " " << data::canonical(v.y()) << " "
              << data::canonical(v.z()) << "\n";
        out << "endloop\nendfacet\n";
      }
    out << "endsolid softchain\n";
    return out.str();
  }

  void StlFile::write(const std::string &path) const
  {
    TextLines::write_all(path, ascii_text(), "STL file");
  }

  StlFile StlFile::subdivided(int levels) const
  {
    StlFile result = *this;
    for (int level = 0; level < levels; ++level)
      {
        std::vector<Triangle> finer;
        for (const auto &t : result.triangles)
          for (const auto &part : split(t))
            finer.push_back(part);
        result.triangles = std::move(finer);
      }
    return result;
  }

  double StlFile::longest_edge() const
  {
    double longest = 0.0;
    for (const auto &t : triangles)
      for (int e = 0; e < 3; ++e)
        longest = std::max(longest, (t[e] - t[(e + 1) % 3]).norm());
    return longest;
  }
} // namespace softchain::geometry
