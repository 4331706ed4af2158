#pragma once
// GmshMesher: runs the gmsh binary on a .geo script and caches the resulting
// ASCII msh 2.2 file under cache_dir/<key>/mesh.msh, the key being a content
// hash of the script text, the -setnumber values and the input files. An
// unchanged design is therefore never meshed twice.
#include <string>
#include <utility>
#include <vector>

namespace softchain::geometry
{
  struct GmshJob
  {
    std::string name;   // for messages (e.g. the .prm path)
    std::string script; // .geo text
    std::vector<std::pair<std::string, double>>      numbers; // -setnumber NAME VALUE
    std::vector<std::pair<std::string, std::string>> files;   // written beside the script: name, content

    // Content hash of script, numbers and files (16 hex digits).
    std::string key() const;

    // The text of a script shipped in the project's meshes/ directory.
    static std::string bundled_script(const std::string &file_name);
  };

  class GmshMesher
  {
  public:
    // gmsh: the binary; default $SOFTCHAIN_GMSH or "gmsh" on the PATH.
    explicit GmshMesher(std::string cache_dir, std::string gmsh = default_binary());

    // Path of the cached mesh of `job`; runs gmsh only if it is not cached.
    // Throws InputError naming the job (with the end of gmsh's log) if gmsh fails.
    std::string mesh(const GmshJob &job);

    int n_runs() const { return n_runs_; } // gmsh invocations by this object

    static std::string default_binary();

  private:
    std::string entry_directory(const GmshJob &job) const; // cache_dir/<key>
    void        run(const GmshJob &job, const std::string &directory);

    std::string cache_dir_;
    std::string gmsh_;
    int         n_runs_ = 0;
  };
} // namespace softchain::geometry
