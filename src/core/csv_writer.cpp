#include "core/csv_writer.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace glint {
namespace {

std::vector<std::string> checked_header(const std::filesystem::path& path, std::vector<std::string> header) {
  if (header.empty()) fail("'{}': a CSV table needs at least one column", path.string());
  std::set<std::string_view> seen;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i].empty()) fail("'{}': CSV column {} has an empty name", path.string(), i + 1);
    if (!seen.insert(header[i]).second) fail("'{}': CSV column '{}' appears twice", path.string(), header[i]);
  }
  return header;
}

}  // namespace

CsvField::CsvField(double value) : text_(fmt::format("{:.6g}", value)) {}

std::string csv_quote(std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(field);
  std::string quoted = "\"";
  for (const char c : field) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

CsvWriter::CsvWriter(std::filesystem::path path, std::vector<std::string> header)
    : header_(checked_header(path, std::move(header))), file_(std::move(path)) {
  write_line(std::vector<std::string_view>(header_.begin(), header_.end()));
}

void CsvWriter::add_row(const std::vector<CsvField>& fields) {
  if (fields.size() != header_.size())
    fail("'{}': row {} has {} fields, but the header has {} columns", file_.path().string(), rows_ + 1,
         fields.size(), header_.size());
  std::vector<std::string_view> texts;
  texts.reserve(fields.size());
  for (const CsvField& field : fields) texts.push_back(field.text());
  write_line(texts);
  ++rows_;
}

void CsvWriter::commit() { file_.commit(); }

void CsvWriter::write_line(const std::vector<std::string_view>& fields) {
  line_.clear();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line_ += ',';
    line_ += csv_quote(fields[i]);
  }
  line_ += '\n';
  file_.write(line_);
}

}  // namespace glint
