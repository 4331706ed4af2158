#pragma once
// ReportRun: `softchain report FILE.prm` and the last stage of
// `softchain run`: writes <output_dir>/report.html (HtmlReport) from the
// outputs of the other stages. `stage_times`: the wall times of the stages
// of `softchain run`, or none when only the report is rebuilt. Returns 0;
// missing or malformed inputs throw data::InputError naming the file.
#include <softchain/report/html_report.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::report
{
  int run_report(const data::PrmFile &prm, const std::string &database_path,
                 const std::string &output_dir,
                 const std::optional<std::vector<StageTime>> &stage_times = std::nullopt);
} // namespace softchain::report
