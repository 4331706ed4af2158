// SamplePlan: reading, writing, cleaning and moving `<database>.plan`.
#include "sample_plan.h"

#include "atomic_file.h"

#include <softchain/data/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace softchain::data
{
  namespace
  {
    namespace fs = std::filesystem;

    // A sample id as the database stores it: a file name without '/' that
    // does not start with '.' (ActuationDatabase::store_sample).
    bool is_sample_id(const std::string &line)
    {
      return !line.empty() && line[0] != '.' && line.find_first_of("/ \t\r") == std::string::npos;
    }

    // A plan as read() gives it: sorted, each id once.
    std::vector<std::string> sorted_once(std::vector<std::string> ids)
    {
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      return ids;
    }
  } // namespace

  SamplePlan::SamplePlan(const std::string &database_path)
    : path_(database_path + ".plan")
  {}

  std::optional<std::vector<std::string>> SamplePlan::read() const
  {
    std::ifstream in(path_);
    if (!in)
      return std::nullopt;
    std::vector<std::string> ids;
    std::string              line;
    for (int number = 1; std::getline(in, line); ++number)
      {
        if (!is_sample_id(line))
          throw InputError(path_ + ":" + std::to_string(number) + ": not a sample id: '" + line +
                           "' (the plan lists one id per line; run `softchain sweep` again to rewrite it)");
        ids.push_back(line);
      }
    return sorted_once(std::move(ids));
  }

  std::vector<std::string> SamplePlan::write(std::vector<std::string> listed) const
  {
    const std::vector<std::string> ids = sorted_once(std::move(listed));
    if (read() == ids)
      return ids; // a rerun of the same .prm rewrites nothing
    write_atomically(path_, [&](const std::string &temporary) {
      std::ofstream out(temporary);
      for (const std::string &id : ids)
        out << id << '\n';
      out.close();
      if (!out)
        throw InputError(path_ + ": could not write the sample plan (disk full?)");
    });
    return ids;
  }

  void SamplePlan::remove_leftovers() const
  {
    remove_temporaries_of(path_);
  }

  void SamplePlan::move_to(const std::string &database_path) const
  {
    if (!fs::exists(path_))
      return;
    fs::rename(path_, SamplePlan(database_path).path_);
  }
} // namespace softchain::data
