// PrmFile / PrmSection: deal.II ParameterHandler syntax without deal.II.
// A logical line is one or more physical lines joined at a trailing "\";
// "#" starts a comment; the statements are "subsection NAME", "end" and
// "set NAME = VALUE".
#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>
#include <softchain/data/text.h>
#include <softchain/data/prm_subsections.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    using Statement = PrmFile::Statement;
    using Kind      = Statement::Kind;

    std::string where(const std::string &path, int line)
    {
      return path + ":" + std::to_string(line) + ": ";
    }

    Statement parse_statement(const std::string &content, int line, const std::string &path)
    {
      const auto word_end = content.find_first_of(" \t");
      const std::string keyword = content.substr(0, word_end);
      const std::string rest =
        word_end == std::string::npos ? "" : trim(content.substr(word_end));
      if (keyword == "end" && rest.empty())
        return {Kind::end, "", "", line};
      if (keyword == "subsection" && !rest.empty())
        return {Kind::subsection, rest, "", line};
      const auto equal = rest.find('=');
      if (keyword == "set" && equal != std::string::npos && !trim(rest.substr(0, equal)).empty())
        return {Kind::set, trim(rest.substr(0, equal)), trim(rest.substr(equal + 1)), line};
      throw InputError(where(path, line) + "expected 'subsection NAME', 'set NAME = VALUE' or "
                                           "'end', found '" + content + "'");
    }

    struct LogicalLine
    {
      std::string content; // comment removed, trimmed
      int         first_line;
    };

    // Joins physical lines ending in "\" with the next one (a trailing "\"
    // on the last line just ends it), then strips "#" comments.
    std::vector<LogicalLine> logical_lines(const std::string &text)
    {
      std::vector<LogicalLine> lines;
      std::istringstream       in(text);
      std::string              physical, joined;
      int                      line = 0, first = 1;
      const auto               finish = [&] {
        lines.push_back({trim(joined.substr(0, joined.find('#'))), first});
        joined.clear();
        first = line + 1;
      };
      while (std::getline(in, physical))
        {
          ++line;
          const std::string stripped = trim(physical);
          const bool continued = !stripped.empty() && stripped.back() == '\\';
          joined += continued ? stripped.substr(0, stripped.size() - 1) + " " : physical;
          if (!continued)
            finish();
        }
      if (first <= line)
        finish();
      return lines;
    }


    // A top-level subsection must be one of prm_subsections(): a misspelled
    // title would otherwise leave all its entries at their defaults.
    void check_known_subsection(const Statement &s, const std::string &path)
    {
      std::string known;
      for (const auto &subsection : prm_subsections())
        {
          if (subsection.title == s.name)
            return;
          known += (known.empty() ? "" : ", ") + subsection.title;
        }
      throw InputError(where(path, s.line) + "unknown subsection '" + s.name +
                       "' (a SoftChain .prm has: " + known + ")");
    }

    // Splits the text into statements; checks that subsection/end balance
    // and that every top-level subsection is one of prm_subsections().
    std::vector<Statement> statements(const std::string &text, const std::string &path)
    {
      std::vector<Statement> result;
      std::vector<int>       opened_at;
      for (const auto &line : logical_lines(text))
        {
          if (line.content.empty())
            continue;
          result.push_back(parse_statement(line.content, line.first_line, path));
          const Statement &s = result.back();
          if (s.kind == Kind::subsection)
            {
              if (opened_at.empty())
                check_known_subsection(s, path);
              opened_at.push_back(s.line);
            }
          else if (s.kind == Kind::end)
            {
              if (opened_at.empty())
                throw InputError(where(path, s.line) + "'end' without a matching 'subsection'");
              opened_at.pop_back();
            }
          else if (opened_at.empty())
            throw InputError(where(path, s.line) + "parameter '" + s.name +
                             "' outside every subsection");
        }
      if (!opened_at.empty())
        throw InputError(where(path, opened_at.back()) + "subsection is never closed by 'end'");
      return result;
    }

    // Calls visit(statement, path of open subsections) for each statement; a
    // subsection line and its end line see the path including that subsection.
    void walk(const std::vector<Statement>                                            &all,
              const std::function<void(const Statement &, const std::vector<std::string> &)> &visit)
    {
      std::vector<std::string> open;
      for (const auto &s : all)
        {
          if (s.kind == Kind::subsection)
            open.push_back(s.name);
          visit(s, open);
          if (s.kind == Kind::end)
            open.pop_back();
        }
    }

    bool is_number(const std::string &text)
    {
      char *end = nullptr;
      std::strtod(text.c_str(), &end);
      return !text.empty() && *end == '\0';
    }

    // `value` with each number between the separators , ; : rewritten by
    // canonical() and the blanks around separators dropped.
    std::string canonical_value(const std::string &value)
    {
      std::string result, token;
      const auto  flush = [&] {
        const std::string t = trim(token);
        result += is_number(t) ? canonical(std::strtod(t.c_str(), nullptr)) : t;
        token.clear();
      };
      for (const char c : value)
        if (c == ',' || c == ';' || c == ':')
          {
            flush();
            result += c;
          }
        else
          token += c;
      flush();
      return result;
    }
  } // namespace

  void PrmSection::declare(const std::string &name, const std::string &default_value,
                           const std::string &documentation, const bool part_of_design)
  {
    entries[name] = Entry{default_value, documentation, 0, part_of_design};
  }

  std::string PrmSection::get(const std::string &name) const
  {
    const auto it = entries.find(name);
    if (it == entries.end())
      throw std::logic_error("PrmSection '" + title + "': parameter '" + name +
                             "' was never declared");
    return it->second.value;
  }

  void PrmSection::require(const bool ok, const std::string &name, const std::string &what) const
  {
    if (!ok)
      throw InputError(describe(name) + ": " + what);
  }

  std::string PrmSection::describe(const std::string &name) const
  {
    const int line = entries.count(name) ? entries.at(name).line : 0;
    return file + (line ? ":" + std::to_string(line) : "") + ": parameter '" + name +
           "' in subsection '" + title + "'";
  }

  double PrmSection::get_double(const std::string &name) const
  {
    const std::string value = get(name);
    require(is_number(value), name, "'" + value + "' is not a number");
    return std::strtod(value.c_str(), nullptr);
  }

  long long PrmSection::parse_integer(const std::string &name) const
  {
    const std::string value = get(name);
    char             *end   = nullptr;
    const long long   v     = std::strtoll(value.c_str(), &end, 10);
    require(!value.empty() && *end == '\0', name, "'" + value + "' is not an integer");
    return v;
  }

  int PrmSection::get_integer(const std::string &name) const
  {
    return static_cast<int>(parse_integer(name));
  }

  int PrmSection::get_integer(const std::string &name, const int low, const int high) const
  {
    const long long v = parse_integer(name);
    require(v >= low && v <= high, name,
            "must lie in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return static_cast<int>(v);
  }

  bool PrmSection::get_bool(const std::string &name) const
  {
    const std::string value = get(name);
    if (value == "true" || value == "yes")
      return true;
    if (value == "false" || value == "no")
      return false;
    throw InputError(describe(name) + ": '" + value + "' is not true/false/yes/no");
  }

  std::vector<std::string> PrmSection::get_list(const std::string &name) const
  {
    std::vector<std::string> items;
    std::istringstream       in(get(name));
    std::string              item;
    while (std::getline(in, item, ','))
      items.push_back(trim(item));
    if (items.size() == 1 && items[0].empty())
      items.clear();
    require(std::count(items.begin(), items.end(), "") == 0, name,
            "empty item in the comma separated list");
    return items;
  }

  std::vector<double> PrmSection::get_double_list(const std::string &name) const
  {
    std::vector<double> values;
    for (const auto &item : get_list(name))
      {
        require(is_number(item), name, "list item '" + item + "' is not a number");
        values.push_back(std::strtod(item.c_str(), nullptr));
      }
    return values;
  }

  std::string PrmSection::get_selection(const std::string              &name,
                                        const std::vector<std::string> &options) const
  {
    const std::string value = get(name);
    if (std::find(options.begin(), options.end(), value) != options.end())
      return value;
    std::string list;
    for (const auto &option : options)
      list += (list.empty() ? "" : ", ") + option;
    throw InputError(describe(name) + ": '" + value + "' is not one of: " + list);
  }

  std::string PrmSection::canonical_values() const
  {
    std::string text;
    for (const auto &[name, entry] : entries)
      if (entry.part_of_design)
        text += title + "/" + name + " = " + canonical_value(entry.value) + "\n";
    return text;
  }

  PrmFile PrmFile::read(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError("cannot open parameter file '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    PrmFile file;
    file.path_       = path;
    file.text_       = text.str();
    file.statements_ = statements(file.text_, path);
    return file;
  }

  void PrmFile::parse_section(const std::string &title, PrmSection &section) const
  {
    section.file  = path_;
    section.title = title;
    walk(statements_, [&](const Statement &s, const std::vector<std::string> &open) {
      if (s.kind != Kind::set || open.empty() || open[0] != title)
        return;
      std::string key;
      for (std::size_t i = 1; i < open.size(); ++i)
        key += open[i] + "/";
      key += s.name;
      const auto entry = section.entries.find(key);
      if (entry == section.entries.end())
        throw InputError(where(path_, s.line) + "unknown parameter '" + key +
                         "' in subsection '" + title + "'");
      entry->second.value = s.value;
      entry->second.line  = s.line;
    });
  }

  std::vector<std::string> PrmFile::subsection_names(const std::string &title) const
  {
    std::vector<std::string> names;
    walk(statements_, [&](const Statement &s, const std::vector<std::string> &open) {
      if (s.kind == Kind::subsection && open.size() == 2 && open[0] == title)
        names.push_back(s.name);
    });
    return names;
  }
} // namespace softchain::data
