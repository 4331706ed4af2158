#pragma once
// ResultsTable: a Markdown table computed from a CSV file that a benchmark
// wrote to benchmarks/results/, so that a documentation page's figures are the
// benchmark's, never typed by hand. A page declares the table by its spec,
// clauses separated by ';', the first the CSV's path relative to the page:
//   ../benchmarks/results/poisson_sweep.csv; where status = converged;
//   rows element; across nu; values error_percent; decimals 2
// Clauses:
//   columns A, B / C, ... a plain table of these columns (default: all); B / C
//                         joins two columns in one cell, "b / c"
//   where C = v1, v2      keep the rows whose C is one of the values (repeatable)
//   rows A, B             one table row per distinct (A, B), in file order,
//   across C              one table column per distinct C, in file order,
//   values V1, V2         holding "V1 / V2" of that row and column ("–": none)
//   decimals N            a pivot's values rounded to N decimals (default,
//                         and in plain tables: as the CSV writes them)
//   headers H1, H2, ...   the header row's texts, one per table column
//                         (default: the column names)
//   nan TEXT              TEXT for a cell whose values are all nan
// A number column is right-aligned. Bad specs and CSV files are
// data::InputErrors naming the clause or column.
#include <softchain/data/csv_table.h>

#include <string>
#include <vector>

namespace softchain::benchmarks
{
  class ResultsTable
  {
  public:
    // Parses `spec`; `page_directory` resolves the CSV's relative path.
    ResultsTable(const std::string &spec, const std::string &page_directory);

    const std::string &csv_path() const { return csv_path_; }
    // The table's Markdown lines (header, alignment row, rows) from the CSV
    // as it is now.
    std::vector<std::string> render() const;

  private:
    struct Filter
    {
      std::string              column;
      std::vector<std::string> values;
    };

    void parse_clause(const std::string &keyword, const std::string &argument);
    std::vector<std::size_t>              kept_rows(const data::CsvTable &csv) const;
    std::vector<std::vector<std::string>> plain(const data::CsvTable &csv) const;
    std::vector<std::vector<std::string>> pivot(const data::CsvTable &csv) const;
    std::string                           rounded(const std::string &text) const;
    // The cell of `row` for "A" or "A / B": the values joined, each rounded
    // if `round`.
    std::string                           cell(const data::CsvTable &csv, std::size_t row,
                                               const std::vector<std::string> &columns, bool round) const;

    std::string              spec_;
    std::string              csv_path_;
    std::vector<std::string> columns_;
    std::vector<Filter>      filters_;
    std::vector<std::string> rows_;
    std::string              across_;
    std::vector<std::string> values_;
    int                      decimals_ = -1; // -1: as written
    std::vector<std::string> headers_;
    std::string              nan_text_ = "nan";
  };
} // namespace softchain::benchmarks
