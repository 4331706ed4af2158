#pragma once
// ResultsPage: a Markdown documentation page whose result tables are
// generated. Each table sits between two HTML comments, which Markdown
// viewers do not show:
//   <!-- table: SPEC -->
//   | ... the table as ResultsTable renders SPEC ... |
//   <!-- end table -->
// regenerated() is the page with every such table rendered anew from its CSV
// file; a page whose text equals it is current. An unclosed table or a bad
// SPEC is a data::InputError naming the page and line.
#include "results_table.h"

#include <string>
#include <vector>

namespace softchain::benchmarks
{
  class ResultsPage
  {
  public:
    static ResultsPage read(const std::string &path);

    const std::string &path() const { return path_; }
    const std::string &text() const { return text_; }
    // The page with its tables rendered from the CSV files as they are now.
    std::string regenerated() const;
    // The page's tables in page order: the first line of each (1-based),
    // its CSV file and whether the page holds it as the CSV file gives it.
    struct TableBlock
    {
      int         line;
      std::string csv_path;
      bool        current;
    };
    std::vector<TableBlock> tables() const;

  private:
    // The table of the opening comment at 0-based `line`; errors name the
    // page and line.
    ResultsTable             table(const std::string &spec, std::size_t line) const;
    std::vector<std::string> render(const std::string &spec, std::size_t line) const;

    std::string path_;
    std::string text_;
  };
} // namespace softchain::benchmarks
