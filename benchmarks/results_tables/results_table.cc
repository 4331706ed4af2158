#include "results_table.h"

#include <softchain/data/input_error.h>
#include <softchain/data/text.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

namespace softchain::benchmarks
{
  namespace
  {
    std::vector<std::string> split(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::size_t              start = 0;
      while (true)
        {
          const std::size_t end = text.find(separator, start);
          items.push_back(data::trim(text.substr(start, end - start)));
          if (end == std::string::npos)
            return items;
          start = end + 1;
        }
    }

    bool is_number(const std::string &text)
    {
      char *end = nullptr;
      std::strtod(text.c_str(), &end);
      return !text.empty() && end == text.c_str() + text.size();
    }

    std::string row_text(const std::vector<std::string> &cells)
    {
      std::string line = "|";
      for (const auto &c : cells)
        line += " " + c + " |";
      return line;
    }
  } // namespace

  ResultsTable::ResultsTable(const std::string &spec, const std::string &page_directory)
    : spec_(spec)
  {
    const std::vector<std::string> clauses = split(spec, ';');
    if (clauses.front().empty())
      throw data::InputError("table spec '" + spec + "': no CSV file");
    csv_path_ = (std::filesystem::path(page_directory) / clauses.front()).lexically_normal().string();
    for (std::size_t i = 1; i < clauses.size(); ++i)
      {
        const std::size_t space = clauses[i].find(' ');
        parse_clause(clauses[i].substr(0, space),
                     space == std::string::npos ? "" : data::trim(clauses[i].substr(space + 1)));
      }
    const bool pivoted = !rows_.empty() || !across_.empty() || !values_.empty();
    if (pivoted && (rows_.empty() || across_.empty() || values_.empty() || !columns_.empty()))
      throw data::InputError("table spec '" + spec + "': a pivot needs rows, across and values, "
                             "and no columns");
    if (!pivoted && decimals_ >= 0)
      throw data::InputError("table spec '" + spec + "': decimals round a pivot's values; a plain "
                             "table shows the CSV's numbers");
  }

  void ResultsTable::parse_clause(const std::string &keyword, const std::string &argument)
  {
    const auto fail = [&](const std::string &why) {
      throw data::InputError("table spec '" + spec_ + "': clause '" + keyword + " " + argument +
                             "': " + why);
    };
    if (argument.empty())
      fail("no argument");
    if (keyword == "columns")
      columns_ = split(argument, ',');
    else if (keyword == "rows")
      rows_ = split(argument, ',');
    else if (keyword == "across")
      across_ = argument;
    else if (keyword == "values")
      values_ = split(argument, ',');
    else if (keyword == "where")
      {
        const std::size_t equals = argument.find('=');
        if (equals == std::string::npos)
          fail("expected 'where COLUMN = value, value'");
        filters_.push_back({data::trim(argument.substr(0, equals)), split(argument.substr(equals + 1), ',')});
      }
    else if (keyword == "decimals")
      {
        decimals_ = is_number(argument) ? std::atoi(argument.c_str()) : -1;
        if (decimals_ < 0 || decimals_ > 17)
          fail("expected 0 to 17 decimals");
      }
    else if (keyword == "headers")
      headers_ = split(argument, ',');
    else if (keyword == "nan")
      nan_text_ = argument;
    else
      fail("unknown clause (columns, where, rows, across, values, decimals, headers, nan)");
  }

  std::vector<std::size_t> ResultsTable::kept_rows(const data::CsvTable &csv) const
  {
    std::vector<std::size_t> kept;
    for (std::size_t r = 0; r < csv.n_rows(); ++r)
      if (std::all_of(filters_.begin(), filters_.end(), [&](const Filter &f) {
            return std::count(f.values.begin(), f.values.end(), csv.text(r, f.column)) > 0;
          }))
        kept.push_back(r);
    return kept;
  }

  std::string ResultsTable::rounded(const std::string &text) const
  {
    if (decimals_ < 0 || !is_number(text) || !std::isfinite(std::strtod(text.c_str(), nullptr)))
      return text;
    char rounded[64];
    std::snprintf(rounded, sizeof(rounded), "%.*f", decimals_, std::strtod(text.c_str(), nullptr));
    return rounded;
  }

  std::string ResultsTable::cell(const data::CsvTable &csv, const std::size_t row,
                                 const std::vector<std::string> &columns, const bool round) const
  {
    std::string joined;
    bool        all_nan = true;
    for (const auto &c : columns)
      {
        const std::string &text = csv.text(row, c);
        all_nan                 = all_nan && text == "nan";
        joined += (joined.empty() ? "" : " / ") + (round ? rounded(text) : text);
      }
    return all_nan ? nan_text_ : joined;
  }

  std::vector<std::vector<std::string>> ResultsTable::plain(const data::CsvTable &csv) const
  {
    const std::vector<std::string> columns = columns_.empty() ? csv.columns() : columns_;
    std::vector<std::vector<std::string>> table = {columns};
    for (const std::size_t r : kept_rows(csv))
      {
        table.emplace_back();
        for (const auto &c : columns)
          table.back().push_back(cell(csv, r, split(c, '/'), false));
      }
    return table;
  }

  std::vector<std::vector<std::string>> ResultsTable::pivot(const data::CsvTable &csv) const
  {
    std::vector<std::vector<std::string>> keys;   // distinct row keys, in file order
    std::vector<std::string>              across; // distinct across values, in file order
    std::map<std::pair<std::vector<std::string>, std::string>, std::string> cells;
    for (const std::size_t r : kept_rows(csv))
      {
        std::vector<std::string> key;
        for (const auto &c : rows_)
          key.push_back(csv.text(r, c));
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
          keys.push_back(key);
        const std::string &a = csv.text(r, across_);
        if (std::find(across.begin(), across.end(), a) == across.end())
          across.push_back(a);
        cells[{key, a}] = cell(csv, r, values_, true);
      }
    std::vector<std::vector<std::string>> table = {rows_};
    std::string value_names;
    for (const auto &v : values_)
      value_names += (value_names.empty() ? "" : " / ") + v;
    for (const auto &a : across)
      table.front().push_back(across_ + " = " + a + (values_.size() > 1 ? ": " + value_names : ""));
    for (const auto &key : keys)
      {
        table.push_back(key);
        for (const auto &a : across)
          {
            const auto found = cells.find({key, a});
            table.back().push_back(found == cells.end() ? "–" : found->second);
          }
      }
    return table;
  }

  std::vector<std::string> ResultsTable::render() const
  {
    const data::CsvTable csv = data::CsvTable::read(csv_path_);
    for (const auto &f : filters_)
      csv.column(f.column); // throws, naming the file and column
    auto table = rows_.empty() ? plain(csv) : pivot(csv);
    if (!headers_.empty())
      {
        if (headers_.size() != table.front().size())
          throw data::InputError("table spec '" + spec_ + "': " + std::to_string(headers_.size()) +
                                 " headers for " + std::to_string(table.front().size()) + " columns");
        table.front() = headers_;
      }
    std::vector<std::string> alignment;
    for (std::size_t c = 0; c < table.front().size(); ++c)
      {
        bool numbers = table.size() > 1;
        for (std::size_t r = 1; r < table.size(); ++r)
          numbers = numbers && (is_number(table[r][c]) || table[r][c] == "–" || table[r][c] == nan_text_);
        alignment.push_back(numbers ? "---:" : "---");
      }
    std::vector<std::string> lines = {row_text(table.front()), row_text(alignment)};
    for (std::size_t r = 1; r < table.size(); ++r)
      lines.push_back(row_text(table[r]));
    return lines;
  }
} // namespace softchain::benchmarks
