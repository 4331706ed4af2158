// results_tables: regenerates the result tables of documentation pages from
// the CSV files the benchmarks wrote (ResultsPage, ResultsTable).
//   results_tables PAGE...           rewrites each page whose tables changed
//   results_tables --check PAGE...   changes nothing; exit 1 if a page's
//                                       tables differ from their CSV files
// A benchmark calls the first form after writing its CSV; the test suite
// runs the second on docs/, so that no table can drift from its data.
#include "results_page.h"

#include <softchain/data/input_error.h>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using softchain::benchmarks::ResultsPage;

namespace
{
  // Names each table of `page` that differs from its CSV file; returns
  // whether there is none.
  bool check(const ResultsPage &page)
  {
    bool current = true;
    for (const auto &table : page.tables())
      if (!table.current)
        {
          std::cout << page.path() << ":" << table.line << ": the table differs from " << table.csv_path
                    << "; regenerate it with results_tables " << page.path() << '\n';
          current = false;
        }
    return current;
  }

  void update(const ResultsPage &page)
  {
    const std::string text = page.regenerated();
    if (text == page.text())
      return;
    std::ofstream(page.path()) << text;
    std::cout << page.path() << ": tables regenerated\n";
  }
} // namespace

int main(int argc, char **argv)
{
  const bool               checking = argc > 1 && std::string(argv[1]) == "--check";
  std::vector<std::string> pages(argv + 1 + (checking ? 1 : 0), argv + argc);
  if (pages.empty())
    {
      std::cerr << "usage: results_tables [--check] PAGE...\n";
      return 1;
    }
  try
    {
      bool current = true;
      for (const auto &path : pages)
        {
          const ResultsPage page = ResultsPage::read(path);
          if (checking)
            current = check(page) && current;
          else
            update(page);
        }
      return current ? 0 : 1;
    }
  catch (const softchain::data::InputError &e)
    {
      std::cerr << "results_tables: " << e.what() << '\n';
      return 1;
    }
}
