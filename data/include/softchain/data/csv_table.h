#pragma once
// CsvTable: the CSV files that join the reduction and chain tiers. One header
// line of column names, then rows of numbers or text; "nan" for no value.
// RFC 4180: cells holding a comma, double quote or line break are quoted.
#include <string>
#include <vector>

namespace softchain::data
{
  class CsvTable
  {
  public:
    explicit CsvTable(std::vector<std::string> columns = {});

    // Reads a file; throws InputError naming file and line on a malformed row
    // (wrong number of cells, unclosed or stray double quote).
    static CsvTable read(const std::string &path);
    // Writes with 17 significant digits, quoting cells as RFC 4180 requires;
    // creates missing parent directories.
    void write(const std::string &path) const;

    const std::vector<std::string> &columns() const { return columns_; }
    std::size_t                     n_rows() const { return rows_.size(); }

    void add_row(const std::vector<std::string> &cells);
    void add_row(const std::vector<double> &values);
    // The text of a number cell as add_row writes it (17 significant digits,
    // "nan" for NaN), for rows that mix text and numbers.
    static std::string cell(double value);

    // Column index by name; throws InputError naming the file and column.
    std::size_t column(const std::string &name) const;
    bool        has_column(const std::string &name) const;
    // Numeric cell; throws InputError naming file, row and column when the
    // cell is not a number ("nan" parses to NaN).
    double             number(std::size_t row, const std::string &column) const;
    const std::string &text(std::size_t row, const std::string &column) const;

  private:
    std::string                           source_; // file name, for messages
    std::vector<std::string>              columns_;
    std::vector<std::vector<std::string>> rows_;
  };
} // namespace softchain::data
