#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/geometry/gmsh_mesher.h>
#include <softchain/geometry/text_lines.h>

#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <unistd.h> // getpid

namespace softchain::geometry
{
  namespace fs = std::filesystem;

  namespace
  {
    const char *const script_name = "input.geo";
    const char *const mesh_name   = "mesh.msh";
    const char *const log_name    = "gmsh.log";

    std::string shell_quote(const std::string &s)
    {
      std::string quoted = "'";
      for (const char c : s)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }

    // What gmsh said: its first error lines (the cause) and the end of its log.
    struct GmshLog
    {
      std::vector<std::string> errors;
      std::deque<std::string>  tail;

      explicit GmshLog(const fs::path &path)
      {
        std::ifstream in(path);
        for (std::string line; std::getline(in, line);)
          {
            if (line.rfind("Error", 0) == 0 && errors.size() < 3)
              errors.push_back(line);
            tail.push_back(line);
            if (tail.size() > 8)
              tail.pop_front();
          }
      }

      // For the message: the errors, or the end of the log if there were none.
      std::string summary() const
      {
        std::string text;
        for (const auto &line : errors.empty() ? std::vector<std::string>(tail.begin(), tail.end()) : errors)
          text += "\n  " + line;
        return text;
      }
    };
  } // namespace

  std::string GmshJob::key() const
  {
    std::ostringstream text;
    text << "gmsh job v1\n" << script.size() << "\n" << script;
    for (const auto &[name, value] : numbers)
      text << "number " << name << " " << data::canonical(value) << "\n";
    for (const auto &[name, content] : files)
      text << "file " << name << " " << content.size() << "\n" << content;
    return data::content_hash(text.str());
  }

  std::string GmshJob::bundled_script(const std::string &file_name)
  {
    return TextLines::read_all((fs::path(SOFTCHAIN_MESHES_DIR) / file_name).string(), "gmsh script");
  }

  GmshMesher::GmshMesher(std::string cache_dir, std::string gmsh)
    : cache_dir_(std::move(cache_dir))
    , gmsh_(std::move(gmsh))
  {}

  std::string GmshMesher::default_binary()
  {
    const char *env = std::getenv("SOFTCHAIN_GMSH");
    return env && *env ? env : "gmsh";
  }

  std::string GmshMesher::entry_directory(const GmshJob &job) const
  {
    return (fs::path(cache_dir_) / job.key()).string();
  }

  std::string GmshMesher::mesh(const GmshJob &job)
  {
    const fs::path directory = entry_directory(job);
    const fs::path mesh      = directory / mesh_name;
    if (!fs::exists(mesh))
      run(job, directory.string());
    return mesh.string();
  }

  void GmshMesher::run(const GmshJob &job, const std::string &directory)
  {
    TextLines::write_all((fs::path(directory) / script_name).string(), job.script, "gmsh script");
    for (const auto &[name, content] : job.files)
      TextLines::write_all((fs::path(directory) / name).string(), content, "gmsh input file");
    // Written under a temporary name (per process) and renamed: an
    // interrupted run never leaves a mesh that looks cached, and two
    // processes meshing the same design do not write into one file.
    const std::string partial = std::string(mesh_name) + ".part" + std::to_string(::getpid());
    std::string command = "cd " + shell_quote(directory) + " && " + shell_quote(gmsh_) +
                          " -3 -format msh22 " + script_name;
    for (const auto &[name, value] : job.numbers)
      command += " -setnumber " + name + " " + data::canonical(value);
    command += " -o " + partial + " > " + log_name + " 2>&1";
    ++n_runs_;
    const int status = std::system(command.c_str());
    const fs::path log_path = fs::path(directory) / log_name;
    const GmshLog  log(log_path);
    if (status != 0 || !log.errors.empty() || !fs::exists(fs::path(directory) / partial))
      {
        std::error_code ignored; // nothing to remove if gmsh wrote nothing
        fs::remove(fs::path(directory) / partial, ignored);
        throw data::InputError(job.name + ": gmsh failed (" + gmsh_ + ", log " +
                               log_path.string() + "):" + log.summary());
      }
    fs::rename(fs::path(directory) / partial, fs::path(directory) / mesh_name);
  }
} // namespace softchain::geometry
