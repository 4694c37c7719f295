#pragma once
// CSV tables (per-frame timings, benchmark results) that appear whole or not at all.
//
// The header is fixed at construction and every row must have exactly as many fields. Rows are written
// to an AtomicFileWriter's temporary as they come (through its 64 KiB buffer), so a 4900-frame run
// does not keep its table in memory, and the file shows up under its name only on commit(): a crashed
// or failed run leaves no half table for a script to plot.
//
// Format (RFC 4180): fields separated by ',', a field containing ',', '"', CR or LF is enclosed in
// double quotes with inner quotes doubled. Lines end with "\n" rather than RFC 4180's "\r\n", as every
// CSV reader (pandas, R, gnuplot, spreadsheets) accepts and Unix tools expect.
#include "core/atomic_file.h"

#include <concepts>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// One field, formatted when it is made: integers exactly, floating point numbers as printf's "%.6g"
// (six significant digits, as much as any timing carries; "nan"/"inf" for non-finite values), text as is.
class CsvField {
public:
  CsvField(std::string_view text) : text_(text) {}
  CsvField(const char* text) : text_(text) {}
  CsvField(const std::string& text) : text_(text) {}
  // bool and char are excluded: `true` or 'x' becoming "1" or "120" is never what was meant.
  template <std::integral T>
    requires(!std::same_as<T, bool> && !std::same_as<T, char>)
  CsvField(T value) : text_(std::to_string(value)) {}
  CsvField(double value);
  CsvField(float value) : CsvField(static_cast<double>(value)) {}

  const std::string& text() const { return text_; }  // unquoted

private:
  std::string text_;
};

// `field` as it appears in a CSV line: unchanged, or quoted when it holds ',', '"', CR or LF.
std::string csv_quote(std::string_view field);

class CsvWriter {
public:
  // Starts the temporary file and writes the header. An empty header, an empty or repeated column
  // name, or an unwritable path is a glint::Error.
  CsvWriter(std::filesystem::path path, std::vector<std::string> header);

  // Appends one row; a row whose field count differs from the header's is a glint::Error naming the
  // file, the row and both counts (and nothing of it is written).
  void add_row(const std::vector<CsvField>& fields);

  // Makes the file visible under its path (see AtomicFileWriter::commit). Without it the destructor
  // removes the temporary and nothing appears.
  void commit();

  const std::filesystem::path& path() const { return file_.path(); }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t row_count() const { return rows_; }

private:
  void write_line(const std::vector<std::string_view>& fields);

  std::vector<std::string> header_;
  AtomicFileWriter file_;
  std::size_t rows_ = 0;
  std::string line_;  // reused for every line
};

}  // namespace glint
