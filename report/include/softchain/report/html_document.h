#pragma once
// HtmlDocument: a small builder for one self-contained HTML page: headings,
// paragraphs, <pre> text, tables (also straight from a CSV file) and figures
// whose images are data: URIs. Every text is escaped; only raw() takes
// markup as it is.
#include <softchain/data/csv_table.h>

#include <sstream>
#include <string>
#include <vector>

namespace softchain::report
{
  class HtmlDocument
  {
  public:
    explicit HtmlDocument(const std::string &title);

    void heading(const std::string &text, int level = 2);
    void paragraph(const std::string &text);
    void preformatted(const std::string &text);
    void raw(const std::string &html);
    void table(const std::vector<std::string>              &header,
               const std::vector<std::vector<std::string>> &rows);
    // The CSV file as a table, numbers with `digits` significant digits.
    void table(const data::CsvTable &csv, int digits = 4);
    // An <img> of `data_uri` (see base64.h) with its caption below it.
    void figure(const std::string &data_uri, const std::string &caption);

    // The page: <!DOCTYPE html> to </html>, with its style sheet.
    std::string str() const;

    static std::string escape(const std::string &text);
    // `text` if it is not a number, else the number with `digits`
    // significant digits ("nan" stays "nan").
    static std::string number(const std::string &text, int digits = 4);

  private:
    std::string        title_;
    std::ostringstream body_;
  };
} // namespace softchain::report
