#pragma once
// The parameter registry of a design's .prm file, without deal.II.
//
// PrmFile reads deal.II ParameterHandler syntax ("subsection NAME",
// "set a = b", "end", "#" comments, "\" line continuation) once, checks the
// structure and that every top-level subsection is one SoftChain knows
// (prm_subsections.h). Each tier then declares the entries of its own
// subsections in a PrmSection and fills it from the file; an unknown or
// malformed entry is an InputError naming file, line and parameter.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace softchain::data
{
  // The entries of one top-level subsection (nested subsections flattened
  // into "Inner/name" keys), with the declared defaults filled in.
  class PrmSection
  {
  public:
    // Declares an entry with its default; PrmFile::parse_section() rejects
    // undeclared ones. An entry that does not change the answer (e.g. how
    // tightly the intermediate load steps converge) is declared with
    // `part_of_design` false and left out of canonical_values().
    void declare(const std::string &name, const std::string &default_value,
                 const std::string &documentation = "", bool part_of_design = true);

    std::string         get(const std::string &name) const;
    double              get_double(const std::string &name) const;
    int                 get_integer(const std::string &name) const;
    // The same, required to lie in [low, high] (an error naming the entry and
    // the range otherwise, also for a number beyond an int).
    int                 get_integer(const std::string &name, int low, int high) const;
    bool                get_bool(const std::string &name) const;
    // Comma separated words, trimmed ("" gives an empty list).
    std::vector<std::string> get_list(const std::string &name) const;
    // Comma separated numbers.
    std::vector<double> get_double_list(const std::string &name) const;
    // The value, which must be one of `options` (error lists them).
    std::string get_selection(const std::string &name,
                              const std::vector<std::string> &options) const;
    // The enumerator whose name is the value: get_enum("Element type",
    // {{"Q1", ElementType::Q1}, ...}); the error lists the names.
    template <typename Enum>
    Enum get_enum(const std::string &name,
                  const std::vector<std::pair<std::string, Enum>> &names) const;

    // "FILE[:LINE]: parameter 'NAME' in subsection 'TITLE'", the prefix of
    // every InputError about that entry (LINE only if the file set it).
    std::string describe(const std::string &name) const;
    // Throws InputError "describe(name): what" unless ok.
    void require(bool ok, const std::string &name, const std::string &what) const;

    // Every entry that is part of the design as "TITLE/NAME = VALUE", one per
    // line in name order, with
    // each number of VALUE rewritten canonically (2.6e5 and 260000 agree):
    // what a design hash needs, independent of how the file is formatted.
    std::string canonical_values() const;

    std::string file;  // for messages
    std::string title; // subsection name
    struct Entry
    {
      std::string value;
      std::string documentation;
      int         line = 0; // 0: default
      bool        part_of_design = true;
    };
    std::map<std::string, Entry> entries;

  private:
    // The entry as an integer, checked to be one (not yet its range).
    long long parse_integer(const std::string &name) const;
  };

  class PrmFile
  {
  public:
    // Reads and tokenises; throws InputError naming the file (and the line
    // of an unbalanced subsection/end, of a line that is no statement, or of
    // a top-level subsection SoftChain does not know).
    static PrmFile read(const std::string &path);

    // Fills `section` (declared entries) from the top-level subsection
    // `title`; a missing subsection leaves the defaults. Throws InputError
    // "FILE:LINE: unknown parameter 'X' in subsection 'T'" for undeclared
    // entries.
    void parse_section(const std::string &title, PrmSection &section) const;

    // Names of the subsections nested directly in top-level `title`, in
    // file order (e.g. the material regions of "Materials").
    std::vector<std::string> subsection_names(const std::string &title) const;

    const std::string &path() const { return path_; }
    // The whole text, for provenance (the database stores it).
    const std::string &text() const { return text_; }

    // One "subsection", "end" or "set" line of the file.
    struct Statement
    {
      enum class Kind
      {
        subsection,
        set,
        end
      };
      Kind        kind;
      std::string name;  // subsection or parameter name
      std::string value; // set only
      int         line;  // first physical line
    };

  private:
    std::string            path_;
    std::string            text_;
    std::vector<Statement> statements_;
  };

  template <typename Enum>
  Enum PrmSection::get_enum(const std::string                                &name,
                            const std::vector<std::pair<std::string, Enum>> &names) const
  {
    std::vector<std::string> options;
    for (const auto &[text, value] : names)
      options.push_back(text);
    const std::string chosen = get_selection(name, options);
    for (const auto &[text, value] : names)
      if (text == chosen)
        return value;
    return names.front().second; // unreachable: get_selection checked
  }
} // namespace softchain::data
