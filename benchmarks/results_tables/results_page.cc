#include "results_page.h"

#include <softchain/data/input_error.h>
#include <softchain/data/text.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace softchain::benchmarks
{
  namespace
  {
    const std::string opening = "<!-- table:";
    const std::string closing = "<!-- end table -->";

    std::vector<std::string> lines_of(const std::string &text)
    {
      std::vector<std::string> lines;
      std::istringstream       in(text);
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    // The spec of an opening comment line, or "" if `line` opens no table.
    std::string spec_of(const std::string &line)
    {
      const std::string trimmed = data::trim(line);
      if (trimmed.rfind(opening, 0) != 0 || trimmed.size() < opening.size() + 3 ||
          trimmed.compare(trimmed.size() - 3, 3, "-->") != 0)
        return "";
      return data::trim(trimmed.substr(opening.size(), trimmed.size() - opening.size() - 3));
    }

    // Calls visit(line index of the opening comment, spec, index of its
    // closing comment) for each table of `lines`.
    template <typename Visit>
    void for_each_table(const std::vector<std::string> &lines, const std::string &path, Visit visit)
    {
      for (std::size_t i = 0; i < lines.size(); ++i)
        {
          const std::string spec = spec_of(lines[i]);
          if (spec.empty())
            continue;
          std::size_t end = i + 1;
          while (end < lines.size() && data::trim(lines[end]) != closing)
            ++end;
          if (end == lines.size())
            throw data::InputError(path + ":" + std::to_string(i + 1) + ": table without '" + closing + "'");
          visit(i, spec, end);
          i = end;
        }
    }
  } // namespace

  ResultsPage ResultsPage::read(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw data::InputError("cannot open documentation page '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    ResultsPage page;
    page.path_ = path;
    page.text_ = text.str();
    return page;
  }

  std::string ResultsPage::regenerated() const
  {
    const std::vector<std::string> lines = lines_of(text_);
    std::vector<std::string>       result;
    std::size_t                    copied = 0;
    for_each_table(lines, path_, [&](std::size_t open, const std::string &spec, std::size_t close) {
      result.insert(result.end(), lines.begin() + copied, lines.begin() + open + 1);
      const auto rows = render(spec, open);
      result.insert(result.end(), rows.begin(), rows.end());
      copied = close;
    });
    result.insert(result.end(), lines.begin() + copied, lines.end());
    std::string text;
    for (const auto &line : result)
      text += line + '\n';
    return text;
  }

  std::vector<ResultsPage::TableBlock> ResultsPage::tables() const
  {
    const std::vector<std::string> lines = lines_of(text_);
    std::vector<TableBlock>        blocks;
    for_each_table(lines, path_, [&](std::size_t open, const std::string &spec, std::size_t close) {
      const std::vector<std::string> held(lines.begin() + open + 1, lines.begin() + close);
      blocks.push_back({static_cast<int>(open + 2), table(spec, open).csv_path(), held == render(spec, open)});
    });
    return blocks;
  }

  ResultsTable ResultsPage::table(const std::string &spec, const std::size_t line) const
  {
    try
      {
        return ResultsTable(spec, std::filesystem::path(path_).parent_path().string());
      }
    catch (const data::InputError &e)
      {
        throw data::InputError(path_ + ":" + std::to_string(line + 1) + ": " + e.what());
      }
  }

  std::vector<std::string> ResultsPage::render(const std::string &spec, const std::size_t line) const
  {
    const ResultsTable t = table(spec, line);
    try
      {
        return t.render();
      }
    catch (const data::InputError &e)
      {
        throw data::InputError(path_ + ":" + std::to_string(line + 1) + ": " + e.what());
      }
  }
} // namespace softchain::benchmarks
