// gold_compare: MOOSE-style regression check of a pipeline's CSV outputs
// against stored reference ("gold") files.
//
//   gold_compare GOLD_DIR OUTPUT_DIR TOLERANCES
//
// Every CSV file under GOLD_DIR (relative path p) must exist as OUTPUT_DIR/p
// with the same columns and rows. Text cells must be equal; number cells a
// (output) and g (gold) must satisfy
//     |a - g| <= rel |g| + floor max_k |g_k|,
// the max over g's column: a relative bound, and a floor at a fraction of
// the column's scale for the entries near zero (a torque about an unloaded
// axis, a coordinate on the symmetry plane). NaN matches only NaN.
// TOLERANCES is a text file of lines
//     <file> <column> <rel> <floor>        # '*' matches any file or column
// (the last matching line wins; '#' starts a comment) and `ignore` instead
// of the two numbers leaves a column out (iteration counts, wall times).
// Exit status: 0 all within tolerance, 1 differences (each printed with file,
// row and column), 2 bad input (a missing file, a malformed tolerance line).
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using softchain::data::CsvTable;

namespace
{
  struct Tolerance
  {
    std::string file, column;
    bool        ignore = false;
    double      rel = 0, floor = 0;
  };

  std::vector<Tolerance> read_tolerances(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw softchain::data::InputError(path + ": cannot read the tolerances");
    std::vector<Tolerance> all;
    std::string            line;
    for (int number = 1; std::getline(in, line); ++number)
      {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        Tolerance          t;
        std::string        rel;
        if (!(words >> t.file))
          continue;
        if (!(words >> t.column >> rel))
          throw softchain::data::InputError(path + ":" + std::to_string(number) +
                                            ": needs '<file> <column> <rel> <floor>' or '<file> <column> ignore'");
        t.ignore = rel == "ignore";
        if (!t.ignore && !(std::istringstream(rel) >> t.rel && words >> t.floor))
          throw softchain::data::InputError(path + ":" + std::to_string(number) + ": '" + line +
                                            "': rel and floor must be numbers");
        all.push_back(t);
      }
    return all;
  }

  const Tolerance &tolerance_of(const std::vector<Tolerance> &all, const std::string &file,
                                const std::string &column)
  {
    static const Tolerance exact{"*", "*", false, 0, 0};
    const Tolerance       *found = &exact;
    for (const auto &t : all)
      if ((t.file == "*" || t.file == file) && (t.column == "*" || t.column == column))
        found = &t;
    return *found;
  }

  bool is_number(const std::string &cell)
  {
    if (cell == "nan")
      return true;
    char *end = nullptr;
    std::strtod(cell.c_str(), &end);
    return !cell.empty() && end == cell.c_str() + cell.size();
  }

  // The differences of one file, printed; returns their count.
  int compare_file(const std::string &name, const CsvTable &gold, const CsvTable &out,
                   const std::vector<Tolerance> &tolerances)
  {
    if (gold.columns() != out.columns() || gold.n_rows() != out.n_rows())
      {
        std::cout << name << ": " << out.n_rows() << " rows of " << out.columns().size()
                  << " columns, the gold file has " << gold.n_rows() << " of " << gold.columns().size()
                  << " (or other column names)\n";
        return 1;
      }
    int differences = 0;
    for (const auto &column : gold.columns())
      {
        const Tolerance &t = tolerance_of(tolerances, name, column);
        if (t.ignore)
          continue;
        double scale = 0;
        for (std::size_t r = 0; r < gold.n_rows(); ++r)
          if (is_number(gold.text(r, column)) && std::isfinite(gold.number(r, column)))
            scale = std::max(scale, std::abs(gold.number(r, column)));
        for (std::size_t r = 0; r < gold.n_rows(); ++r)
          {
            const std::string &g = gold.text(r, column), &a = out.text(r, column);
            bool               same = g == a;
            if (!same && is_number(g) && is_number(a))
              {
                const double x = out.number(r, column), y = gold.number(r, column);
                same = (std::isnan(x) && std::isnan(y)) ||
                       std::abs(x - y) <= t.rel * std::abs(y) + t.floor * scale;
              }
            if (!same && ++differences <= 20)
              std::cout << name << ", row " << r + 2 << ", column " << column << ": " << a
                        << " against the gold " << g << " (rel " << t.rel << ", floor " << t.floor
                        << " of the column's largest |value| " << scale << ")\n";
          }
      }
    return differences;
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc != 4)
    {
      std::cerr << "usage: gold_compare GOLD_DIR OUTPUT_DIR TOLERANCES\n";
      return 2;
    }
  try
    {
      const fs::path gold_dir(argv[1]), out_dir(argv[2]);
      const auto     tolerances = read_tolerances(argv[3]);
      std::vector<std::string> files;
      for (const auto &entry : fs::recursive_directory_iterator(gold_dir))
        if (entry.path().extension() == ".csv")
          files.push_back(fs::relative(entry.path(), gold_dir).string());
      std::sort(files.begin(), files.end());
      if (files.empty())
        throw softchain::data::InputError(gold_dir.string() + ": no gold CSV file");
      int differences = 0;
      for (const auto &name : files)
        {
          if (!fs::exists(out_dir / name))
            throw softchain::data::InputError((out_dir / name).string() + ": missing (the gold file " +
                                              name + " has no output to compare)");
          differences += compare_file(name, CsvTable::read((gold_dir / name).string()),
                                      CsvTable::read((out_dir / name).string()), tolerances);
        }
      std::cout << files.size() << " files compared, " << differences << " cells differ\n";
      return differences == 0 ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gold_compare: " << e.what() << '\n';
      return 2;
    }
}
