#include "gl/shader_includes.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace glint {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

std::string_view skip_spaces(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  return text;
}

// The preprocessor directive a line starts with ("include" for "  #  include ..."), and the text
// after it; nullopt for lines that are not directives.
struct Directive {
  std::string_view word;
  std::string_view rest;
};
std::optional<Directive> directive_of(std::string_view line) {
  line = skip_spaces(line);
  if (line.empty() || line.front() != '#') return std::nullopt;
  line = skip_spaces(line.substr(1));
  std::size_t length = 0;
  while (length < line.size() && is_identifier_char(line[length])) ++length;
  return Directive{line.substr(0, length), line.substr(length)};
}

class IncludeExpander {
public:
  IncludeExpander(const ShaderIncludeLookup& lookup, std::string_view display_root)
      : lookup_(lookup), display_root_(display_root) {}

  ExpandedShaderSource run(std::string_view name, std::string_view source) {
    expand(name, source);
    return std::move(result_);
  }

private:
  struct Open {  // a file being expanded (on the include stack)
    std::string name;
    int number;  // its GLSL source-string number
  };

  std::string display(std::string_view name) const { return std::string(display_root_).append(name); }

  // Appends `source` (the file `name`) with its includes expanded; returns nothing, fills result_.
  void expand(std::string_view name, std::string_view source) {
    const int number = static_cast<int>(result_.files.size());
    result_.files.push_back(display(name));
    expanded_.emplace_back(name);
    stack_.push_back({std::string(name), number});

    int line_number = 0;
    std::size_t start = 0;
    while (start < source.size()) {
      std::size_t end = source.find('\n', start);
      const bool has_newline = end != std::string_view::npos;
      if (!has_newline) end = source.size();
      const std::string_view line = source.substr(start, end - start);
      start = end + 1;
      ++line_number;

      const auto directive = directive_of(line);
      if (directive && directive->word == "version" && stack_.size() > 1)
        fail("{}:{}: an included file must not declare #version (only the top shader file does)", display(name),
             line_number);
      if (!directive || directive->word != "include") {
        result_.text.append(line);
        // Text from an included file always ends its last line, so the #line that follows starts a line.
        if (has_newline || stack_.size() > 1) result_.text.push_back('\n');
        continue;
      }

      const std::string included = parse_include_name(directive->rest, name, line_number);
      if (std::find(expanded_.begin(), expanded_.end(), included) != expanded_.end()) {
        for (const Open& open : stack_)
          if (open.name == included) fail("{}:{}: include cycle: {}", display(name), line_number, cycle_text(included));
        // Once-only: a comment keeps the line count, so no #line is needed.
        result_.text.append("// #include \"").append(included).append("\": already included\n");
        continue;
      }
      if (static_cast<int>(stack_.size()) >= kMaxShaderIncludeDepth)
        fail("{}:{}: includes nested deeper than {} files, at \"{}\"", display(name), line_number,
             kMaxShaderIncludeDepth, included);
      const std::optional<std::string_view> included_source = lookup_(included);
      if (!included_source)
        fail("{}:{}: unknown include file \"{}\" (names are relative to {}; a new file needs a rebuild to be "
             "embedded)",
             display(name), line_number, included, display_root_.empty() ? "the shader root" : display_root_);

      result_.text.append(fmt::format("#line 1 {}\n", result_.files.size()));
      expand(included, *included_source);
      result_.text.append(fmt::format("#line {} {}\n", line_number + 1, number));
    }
    stack_.pop_back();
  }

  std::string parse_include_name(std::string_view rest, std::string_view name, int line_number) const {
    const auto malformed = [&] {
      fail("{}:{}: malformed #include; write #include \"file.glsl\" (quoted, relative to {})", display(name),
           line_number, display_root_.empty() ? "the shader root" : display_root_);
    };
    rest = skip_spaces(rest);
    if (rest.empty() || rest.front() != '"') malformed();
    const std::size_t close = rest.find('"', 1);
    if (close == std::string_view::npos || close == 1) malformed();
    const std::string_view included = rest.substr(1, close - 1);
    const std::string_view tail = skip_spaces(rest.substr(close + 1));
    if (!tail.empty() && tail.substr(0, 2) != "//") malformed();
    return std::string(included);
  }

  // "a -> b -> a" for the part of the stack from `name` to the top, closed with `name` again.
  std::string cycle_text(std::string_view name) const {
    std::string text;
    bool in_cycle = false;
    for (const Open& open : stack_) {
      in_cycle = in_cycle || open.name == name;
      if (in_cycle) text.append(display(open.name)).append(" -> ");
    }
    return text.append(display(name));
  }

  const ShaderIncludeLookup& lookup_;
  std::string_view display_root_;
  ExpandedShaderSource result_;
  std::vector<std::string> expanded_;  // every file expanded so far (once-only)
  std::vector<Open> stack_;            // files being expanded, outermost first
};

}  // namespace

ExpandedShaderSource expand_shader_includes(std::string_view name, std::string_view source,
                                            const ShaderIncludeLookup& lookup, std::string_view display_root) {
  return IncludeExpander(lookup, display_root).run(name, source);
}

std::string add_shader_defines(std::string_view source, std::span<const std::string_view> defines) {
  if (defines.empty()) return std::string(source);
  const std::size_t first_line_end = std::min(source.find('\n'), source.size());
  const std::optional<Directive> first = directive_of(source.substr(0, first_line_end));
  if (!first || first->word != "version") fail("shader defines: the source must start with its #version line");
  std::string text(source.substr(0, first_line_end));
  text += '\n';
  for (const std::string_view name : defines) {
    const bool identifier = !name.empty() && std::isdigit(static_cast<unsigned char>(name.front())) == 0 &&
                            std::all_of(name.begin(), name.end(), is_identifier_char);
    if (!identifier) fail("shader defines: '{}' is not a GLSL identifier", name);
    text += fmt::format("#define {} 1\n", name);
  }
  text += "#line 2 0\n";
  if (first_line_end < source.size()) text += source.substr(first_line_end + 1);
  return text;
}

}  // namespace glint
