// The report end to end: `softchain run` on the tiny bender with plots on
// writes report.html, and headless Chromium loads every image of it from
// that one file (chromium is a Debian package that scripts/setup installs;
// without it this test fails). `softchain report` rebuilds the page alone,
// and names the missing file when there are no outputs.
#include "tiny_design.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using softchain::testing::ScratchDirectory;
using softchain::testing::TinyDesign;

namespace
{
  namespace fs = std::filesystem;

  std::string read_text(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  struct ImageCount
  {
    int loaded = -1, total = -1;
  };

  // Opens a copy of `html` (with `extra` markup added to its body) in
  // headless Chromium, whose script writes how many images decoded to a
  // nonzero width into the page; --dump-dom prints the page after the load
  // event. We run as root, hence --no-sandbox; a profile of its own keeps
  // parallel runs apart.
  ImageCount images_in_chromium(const std::string &html, const ScratchDirectory &scratch,
                                const std::string &extra = "")
  {
    const std::string script =
      "<script>window.addEventListener('load', () => {"
      " const images = Array.from(document.images);"
      " const loaded = images.filter(i => i.complete && i.naturalWidth > 0).length;"
      " const p = document.createElement('p');"
      " p.textContent = 'images loaded ' + loaded + ' of ' + images.length;"
      " document.body.appendChild(p); });</script>\n";
    std::string page = read_text(html);
    page.insert(page.rfind("</body>"), extra + script);
    std::ofstream(scratch.file("page.html")) << page;
    const std::string command = "chromium --headless --no-sandbox --disable-gpu "
                                "--virtual-time-budget=10000 --user-data-dir=" +
                                scratch.file("profile") + " --dump-dom file://" +
                                scratch.file("page.html") + " > " + scratch.file("dom.html") +
                                " 2> " + scratch.file("chromium.log");
    std::system(command.c_str());
    const std::string dom = read_text(scratch.file("dom.html"));
    std::smatch       match;
    if (!std::regex_search(dom, match, std::regex("images loaded (\\d+) of (\\d+)")))
      FAIL("headless chromium did not report the images (is the Debian package chromium "
           "installed? scripts/setup installs it):\n"
           << read_text(scratch.file("chromium.log")));
    return {std::stoi(match[1]), std::stoi(match[2])};
  }

  int png_files_under(const std::string &directory)
  {
    int n = 0;
    for (const auto &entry : fs::recursive_directory_iterator(directory))
      n += entry.path().extension() == ".png";
    return n;
  }
} // namespace

TEST_CASE("softchain run writes a report whose every image loads in headless Chromium")
{
  // The tiny pipeline of run_test.cc, with the gnuplot plots on so that the
  // report embeds PNGs too.
  const TinyDesign design = softchain::testing::pipeline_design("report_pipeline", true);
  const auto outcome = design.run("run");
  INFO(outcome.output);
  REQUIRE(outcome.status == 0);
  CHECK(outcome.output.find("stage 4/4: report") != std::string::npos);
  const std::string report = design.output() + "/report.html";
  REQUIRE(fs::exists(report));
  CHECK(outcome.output.find(report) != std::string::npos); // in the output list
  CHECK(read_text(report).find("<td>FEM sample sweep</td>") != std::string::npos);

  // Three SVG pictures (0, 40, 80 kPa), one of the chain over the FEM finger
  // per validation sample (the tiny design has one), and every PNG that the
  // reduction and the chain drew: the validation plot and at least one
  // stiffness plot.
  const int pngs = png_files_under(design.output());
  CHECK(pngs >= 2);
  const ScratchDirectory browser("report_browser");
  const ImageCount       images = images_in_chromium(report, browser);
  CHECK(images.total == 3 + 1 + pngs);
  CHECK(images.loaded == images.total);

  // The check itself sees a broken image: a PNG cut after its signature.
  const ImageCount broken =
    images_in_chromium(report, browser, "<img src=\"data:image/png;base64,iVBORw0KGgo=\">");
  CHECK(broken.total == images.total + 1);
  CHECK(broken.loaded == images.total);

  // `softchain report` alone rebuilds it, without the stage times.
  const auto rebuilt = design.run("report");
  CHECK(rebuilt.status == 0);
  CHECK(read_text(report).find("not measured in this run") != std::string::npos);
}

TEST_CASE("softchain report without the outputs of a run names the missing file")
{
  TinyDesign design("report_missing", "set Pressure sweep = 1e3");
  const auto outcome = design.run("report");
  INFO(outcome.output);
  CHECK(outcome.status == 1);
  CHECK(outcome.output.find(design.database() + ": not found") != std::string::npos);
}
