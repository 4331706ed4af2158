#include <softchain/data/input_error.h>
#include <softchain/report/report_run.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace softchain::report
{
  int run_report(const data::PrmFile &prm, const std::string &database_path,
                 const std::string &output_dir, const std::optional<std::vector<StageTime>> &stage_times)
  {
    HtmlReport report(prm, database_path, output_dir);
    if (stage_times)
      report.set_stage_times(*stage_times);
    // Written beside and renamed over: a reader never sees half a report.
    const std::string path = output_dir + "/report.html", partial = path + ".partial";
    {
      std::ofstream file(partial, std::ios::binary);
      file << report.html();
      if (!file)
        throw data::InputError(partial + ": cannot write the report");
    }
    std::filesystem::rename(partial, path);
    std::cout << "report: " << path << " (" << std::filesystem::file_size(path) / 1024 << " KiB)\n";
    return 0;
  }
} // namespace softchain::report
