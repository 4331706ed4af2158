// CsvTable: RFC 4180 CSV, one header line; numbers written with 17
// significant digits, "nan" for NaN. Only cells holding a comma, a double
// quote or a line break are quoted, so numeric tables stay plain.
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    // Reads the records of an RFC 4180 file: cells split at commas outside
    // double quotes, "" inside quotes is one quote, line breaks inside quotes
    // belong to the cell, a record ends at LF or CRLF outside quotes. Blank
    // lines are skipped. Malformed text throws InputError naming file and line.
    class RecordReader
    {
    public:
      RecordReader(std::istream &in, const std::string &path)
        : in_(in)
        , path_(path)
      {}

      // The next record's cells; false at the end of the file.
      bool next(std::vector<std::string> &cells)
      {
        cells.assign(1, "");
        record_line_ = line_;
        State state  = State::cell_start;
        bool  blank  = true; // nothing but a line end read so far
        const int eof = std::char_traits<char>::eof();
        for (int c; (c = in_.get()) != eof;)
          {
            if (c == '\r' && state != State::quoted && (in_.peek() == '\n' || in_.peek() == eof))
              continue; // CRLF ends a line like LF
            if (c == '\n')
              ++line_;
            if (c == '\n' && state != State::quoted)
              {
                if (!blank)
                  return true;
                record_line_ = line_;
                continue;
              }
            blank = false;
            state = step(state, char(c), cells);
          }
        if (state == State::quoted)
          throw error(quote_line_, "quoted cell not closed before the end of the file");
        return !blank;
      }

      // Line on which the record last returned by next() starts.
      int record_line() const { return record_line_; }

      InputError error(int line, const std::string &what) const
      {
        return InputError(path_ + ":" + std::to_string(line) + ": " + what);
      }

    private:
      enum class State
      {
        cell_start,
        unquoted,
        quoted,
        closing_quote // a quote inside a quoted cell: "" or the cell's end
      };

      // Consumes one character of a record (not a record-ending line break).
      State step(const State state, const char c, std::vector<std::string> &cells)
      {
        switch (state)
          {
            case State::cell_start:
              if (c == '"')
                {
                  quote_line_ = line_;
                  return State::quoted;
                }
              [[fallthrough]];
            case State::unquoted:
              if (c == ',')
                return next_cell(cells);
              if (c == '"')
                throw error(line_, "double quote inside an unquoted cell (quote the cell and "
                                   "double the quote)");
              cells.back() += c;
              return State::unquoted;
            case State::quoted:
              if (c == '"')
                return State::closing_quote;
              cells.back() += c;
              return State::quoted;
            case State::closing_quote:
              if (c == '"')
                {
                  cells.back() += '"';
                  return State::quoted;
                }
              if (c == ',')
                return next_cell(cells);
              throw error(line_, "text after the closing quote of a cell");
          }
        return state;
      }

      static State next_cell(std::vector<std::string> &cells)
      {
        cells.emplace_back();
        return State::cell_start;
      }

      std::istream      &in_;
      const std::string &path_;
      int                line_        = 1; // line of the next character
      int                record_line_ = 1;
      int                quote_line_  = 1;
    };

    // A cell as RFC 4180 writes it: quoted when it holds a comma, a double
    // quote, CR or LF (inner quotes doubled), otherwise as it is. A record of
    // one empty cell is quoted too, so that it is not read as a blank line.
    std::string field(const std::string &cell, const bool only_cell)
    {
      if (cell.find_first_of(",\"\r\n") == std::string::npos && !(only_cell && cell.empty()))
        return cell;
      std::string quoted = "\"";
      for (const char c : cell)
        quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
      return quoted + '"';
    }
  } // namespace

  std::string CsvTable::cell(double value)
  {
    if (std::isnan(value))
      return "nan";
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", value);
    return text;
  }

  CsvTable::CsvTable(std::vector<std::string> columns)
    : columns_(std::move(columns))
  {}

  CsvTable CsvTable::read(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError("cannot open CSV file '" + path + "'");
    RecordReader             records(in, path);
    std::vector<std::string> cells;
    if (!records.next(cells))
      throw InputError(path + ":1: empty CSV file, expected a header line");
    CsvTable table(cells);
    table.source_ = path;
    while (records.next(cells))
      {
        if (cells.size() != table.columns_.size())
          throw records.error(records.record_line(),
                              "expected " + std::to_string(table.columns_.size()) +
                                " cells, found " + std::to_string(cells.size()));
        table.rows_.push_back(cells);
      }
    return table;
  }

  void CsvTable::write(const std::string &path) const
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(path);
    if (!out)
      throw InputError("cannot write CSV file '" + path + "'");
    const auto write_line = [&out](const std::vector<std::string> &cells) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        out << (i ? "," : "") << field(cells[i], cells.size() == 1);
      out << '\n';
    };
    write_line(columns_);
    for (const auto &row : rows_)
      write_line(row);
    if (!out)
      throw InputError("error while writing CSV file '" + path + "'");
  }

  void CsvTable::add_row(const std::vector<std::string> &cells)
  {
    if (cells.size() != columns_.size())
      throw std::logic_error("CsvTable::add_row: " + std::to_string(cells.size()) +
                             " cells for " + std::to_string(columns_.size()) + " columns");
    rows_.push_back(cells);
  }

  void CsvTable::add_row(const std::vector<double> &values)
  {
    std::vector<std::string> cells;
    for (const double v : values)
      cells.push_back(cell(v));
    add_row(cells);
  }

  bool CsvTable::has_column(const std::string &name) const
  {
    for (const auto &c : columns_)
      if (c == name)
        return true;
    return false;
  }

  std::size_t CsvTable::column(const std::string &name) const
  {
    for (std::size_t i = 0; i < columns_.size(); ++i)
      if (columns_[i] == name)
        return i;
    throw InputError("CSV file '" + source_ + "' has no column '" + name + "'");
  }

  const std::string &CsvTable::text(std::size_t row, const std::string &column_name) const
  {
    if (row >= rows_.size())
      throw InputError("CSV file '" + source_ + "' has no row " + std::to_string(row + 1));
    return rows_[row][column(column_name)];
  }

  double CsvTable::number(std::size_t row, const std::string &column_name) const
  {
    const std::string &cell = text(row, column_name);
    char              *end  = nullptr;
    const double       v    = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0')
      throw InputError("CSV file '" + source_ + "', row " + std::to_string(row + 1) +
                       ", column '" + column_name + "': '" + cell + "' is not a number");
    return v;
  }
} // namespace softchain::data
