#pragma once
// Runs the built glint executable as a user would and captures its exit code, stdout and stderr.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

#include "support/test_paths.h"

namespace glint::testing {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// A path in double quotes, for a command line (built by appending: GCC 12 warns falsely about
// "literal" + std::string under -O2).
inline std::string quoted(const std::filesystem::path& path) {
  std::string text = "\"";
  text += path.string();
  text += "\"";
  return text;
}

// The rows of a CSV file written by glint (no quoting), each split at commas; a trailing comma gives a
// last empty field.
inline std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream text(read_text_file(path));
  for (std::string line; std::getline(text, line);) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

// `arguments` is appended to the command line as is (quote paths yourself).
inline CliResult run_glint(const std::string& arguments) {
  const auto dir = std::filesystem::temp_directory_path() / ("glint_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  // Built by appending (GCC 12 warns falsely about "literal" + std::string under -O2).
  std::string command;
  for (const std::string& part : {std::string("\""), cli_path(), std::string("\" "), arguments, std::string(" >\""),
                                  out.string(), std::string("\" 2>\""), err.string(), std::string("\"")})
    command += part;
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text_file(out);
  result.err = read_text_file(err);
  std::filesystem::remove_all(dir);
  return result;
}

inline int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

}  // namespace glint::testing
