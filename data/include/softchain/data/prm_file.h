#pragma once
// PrmFile: reads deal.II ParameterHandler syntax ("subsection NAME", "set a = b",
// "end", "#" comments, "\" line continuation) for the tiers that do not link
// deal.II. Each tier declares the entries of its own top-level subsections and
// gets an InputError naming file, line and parameter for unknown or malformed
// entries. The FEM tier parses the rest with deal.II's ParameterHandler.
#include <map>
#include <string>
#include <vector>

namespace softchain::data
{
  // The entries of one subsection (nested subsections flattened into
  // "Inner/name" keys), with the declared defaults filled in.
  class PrmSection
  {
  public:
    // Declares an entry with its default; parse_section() rejects undeclared ones.
    void declare(const std::string &name, const std::string &default_value,
                 const std::string &documentation = "");

    double              get_double(const std::string &name) const;
    int                 get_integer(const std::string &name) const;
    bool                get_bool(const std::string &name) const;
    std::string         get(const std::string &name) const;
    std::vector<double> get_double_list(const std::string &name) const; // comma separated
    // Added: comma separated words, trimmed ("" gives an empty list).
    std::vector<std::string> get_list(const std::string &name) const;
    // Added: "FILE[:LINE]: parameter 'NAME' in subsection 'TITLE'", the prefix
    // of every InputError about that entry (LINE only if the file set it).
    std::string describe(const std::string &name) const;
    // Throws InputError "describe(name): what" unless ok.
    void require(bool ok, const std::string &name, const std::string &what) const;

    std::string file;  // for messages
    std::string title; // subsection name
    struct Entry
    {
      std::string value;
      std::string documentation;
      int         line = 0; // 0: default
    };
    std::map<std::string, Entry> entries;
  };

  class PrmFile
  {
  public:
    // Reads and tokenises; throws InputError naming the file (and line for
    // unbalanced subsection/end or a line that is neither).
    static PrmFile read(const std::string &path);

    // Fills `section` (declared entries) from the top-level subsection
    // `title`; a missing subsection leaves the defaults. Throws InputError
    // "FILE:LINE: unknown parameter 'X' in subsection 'T'" for undeclared
    // entries.
    void parse_section(const std::string &title, PrmSection &section) const;

    // The file's text with the named top-level subsections removed (line
    // numbers kept by blank lines), for deal.II's ParameterHandler.
    std::string text_without(const std::vector<std::string> &titles) const;

    const std::string &path() const { return path_; }
    const std::string &text() const { return text_; }

  private:
    std::string path_;
    std::string text_;
  };
} // namespace softchain::data
