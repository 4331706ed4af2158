// CsvTable: comma separated cells, no quoting (cells never hold commas), one
// header line; numbers written with 17 significant digits, "nan" for NaN.
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    std::vector<std::string> split_cells(const std::string &line)
    {
      std::vector<std::string> cells;
      std::size_t              start = 0;
      while (true)
        {
          const std::size_t comma = line.find(',', start);
          cells.push_back(line.substr(start, comma - start));
          if (comma == std::string::npos)
            return cells;
          start = comma + 1;
        }
    }

    std::string strip_line_end(std::string line)
    {
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      return line;
    }
  } // namespace

  std::string CsvTable::cell(double value)
  {
    if (std::isnan(value))
      return "nan";
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", value);
    return text;
  }

  CsvTable::CsvTable(std::vector<std::string> columns)
    : columns_(std::move(columns))
  {}

  CsvTable CsvTable::read(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError("cannot open CSV file '" + path + "'");
    std::string line;
    if (!std::getline(in, line))
      throw InputError(path + ":1: empty CSV file, expected a header line");
    CsvTable table(split_cells(strip_line_end(line)));
    table.source_ = path;
    for (int line_number = 2; std::getline(in, line); ++line_number)
      {
        line = strip_line_end(line);
        if (line.empty())
          continue;
        auto cells = split_cells(line);
        if (cells.size() != table.columns_.size())
          throw InputError(path + ":" + std::to_string(line_number) + ": expected " +
                           std::to_string(table.columns_.size()) + " cells, found " +
                           std::to_string(cells.size()));
        table.rows_.push_back(std::move(cells));
      }
    return table;
  }

  void CsvTable::write(const std::string &path) const
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(path);
    if (!out)
      throw InputError("cannot write CSV file '" + path + "'");
    const auto write_line = [&out](const std::vector<std::string> &cells) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        out << (i ? "," : "") << cells[i];
      out << '\n';
    };
    write_line(columns_);
    for (const auto &row : rows_)
      write_line(row);
    if (!out)
      throw InputError("error while writing CSV file '" + path + "'");
  }

  void CsvTable::add_row(const std::vector<std::string> &cells)
  {
    if (cells.size() != columns_.size())
      throw std::logic_error("CsvTable::add_row: " + std::to_string(cells.size()) +
                             " cells for " + std::to_string(columns_.size()) + " columns");
    rows_.push_back(cells);
  }

  void CsvTable::add_row(const std::vector<double> &values)
  {
    std::vector<std::string> cells;
    for (const double v : values)
      cells.push_back(cell(v));
    add_row(cells);
  }

  bool CsvTable::has_column(const std::string &name) const
  {
    for (const auto &c : columns_)
      if (c == name)
        return true;
    return false;
  }

  std::size_t CsvTable::column(const std::string &name) const
  {
    for (std::size_t i = 0; i < columns_.size(); ++i)
      if (columns_[i] == name)
        return i;
    throw InputError("CSV file '" + source_ + "' has no column '" + name + "'");
  }

  const std::string &CsvTable::text(std::size_t row, const std::string &column_name) const
  {
    if (row >= rows_.size())
      throw InputError("CSV file '" + source_ + "' has no row " + std::to_string(row + 1));
    return rows_[row][column(column_name)];
  }

  double CsvTable::number(std::size_t row, const std::string &column_name) const
  {
    const std::string &cell = text(row, column_name);
    char              *end  = nullptr;
    const double       v    = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0')
      throw InputError("CSV file '" + source_ + "', row " + std::to_string(row + 1) +
                       ", column '" + column_name + "': '" + cell + "' is not a number");
    return v;
  }
} // namespace softchain::data
