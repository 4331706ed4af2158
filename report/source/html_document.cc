#include <softchain/report/html_document.h>

#include <cstdlib>

namespace softchain::report
{
  HtmlDocument::HtmlDocument(const std::string &title)
    : title_(title)
  {
    heading(title, 1);
  }

  std::string HtmlDocument::escape(const std::string &text)
  {
    std::string escaped;
    for (const char c : text)
      switch (c)
        {
          case '<': escaped += "&lt;"; break;
          case '>': escaped += "&gt;"; break;
          case '&': escaped += "&amp;"; break;
          case '"': escaped += "&quot;"; break;
          default: escaped += c;
        }
    return escaped;
  }

  std::string HtmlDocument::number(const std::string &text, const int digits)
  {
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0')
      return text;
    std::ostringstream formatted;
    formatted.precision(digits);
    formatted << value;
    return formatted.str();
  }

  void HtmlDocument::heading(const std::string &text, const int level)
  {
    body_ << "<h" << level << ">" << escape(text) << "</h" << level << ">\n";
  }

  void HtmlDocument::paragraph(const std::string &text)
  {
    body_ << "<p>" << escape(text) << "</p>\n";
  }

  void HtmlDocument::preformatted(const std::string &text)
  {
    body_ << "<pre>" << escape(text) << "</pre>\n";
  }

  void HtmlDocument::raw(const std::string &html) { body_ << html; }

  void HtmlDocument::table(const std::vector<std::string>              &header,
                           const std::vector<std::vector<std::string>> &rows)
  {
    body_ << "<table>\n<tr>";
    for (const auto &name : header)
      body_ << "<th>" << escape(name) << "</th>";
    body_ << "</tr>\n";
    for (const auto &row : rows)
      {
        body_ << "<tr>";
        for (const auto &cell : row)
          body_ << "<td>" << escape(cell) << "</td>";
        body_ << "</tr>\n";
      }
    body_ << "</table>\n";
  }

  void HtmlDocument::table(const data::CsvTable &csv, const int digits)
  {
    std::vector<std::vector<std::string>> rows(csv.n_rows());
    for (std::size_t r = 0; r < csv.n_rows(); ++r)
      for (const auto &column : csv.columns())
        rows[r].push_back(number(csv.text(r, column), digits));
    table(csv.columns(), rows);
  }

  void HtmlDocument::figure(const std::string &data_uri, const std::string &caption)
  {
    body_ << "<figure><img src=\"" << data_uri << "\" alt=\"" << escape(caption)
          << "\"><figcaption>" << escape(caption) << "</figcaption></figure>\n";
  }

  std::string HtmlDocument::str() const
  {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
           escape(title_) +
           "</title>\n<style>\n"
           "body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; }\n"
           "table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; display: block;"
           " overflow-x: auto; max-width: 100%; }\n"
           "th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }\n"
           "th { background: #eee; }\n"
           "figure { display: inline-block; margin: 0.5em; vertical-align: top; max-width: 100%; }\n"
           "figure img { max-width: 100%; border: 1px solid #ddd; }\n"
           "figcaption { font-size: 0.9em; max-width: 480px; }\n"
           "pre { background: #f6f6f6; padding: 0.5em; overflow-x: auto; font-size: 0.85em; }\n"
           ".holds { color: #060; font-weight: bold; }\n"
           ".fails { color: #a00; font-weight: bold; }\n"
           ".unknown { color: #666; font-weight: bold; }\n"
           "</style>\n</head>\n<body>\n" +
           body_.str() + "</body>\n</html>\n";
  }
} // namespace softchain::report
