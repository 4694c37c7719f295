#include "scene/obj_validation.h"

#include "core/error.h"
#include "core/untrusted_text.h"
#include "scene/obj_text_parsing.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace glint {
namespace {

using obj_text::parse_float;
using obj_text::parse_integer;
using obj_text::take_token;

// The state of the pass, so that the per-statement checks can name the file and line.
class ObjTextValidator {
public:
  explicit ObjTextValidator(std::string_view file_label) : file_(file_label) {}

  void check_line(std::string_view line, std::size_t line_number);
  ObjTextSummary finish();

private:
  template <typename... Args>
  [[noreturn]] void fail_here(fmt::format_string<Args...> format, Args&&... args) const {
    fail("{}:{}: {}", file_, line_, fmt::format(format, std::forward<Args>(args)...));
  }

  // Reads the numbers after a `v`, `vt` or `vn` keyword; the count must be in [min_count, max_count].
  void check_numbers(std::string_view keyword, std::string_view rest, int min_count, int max_count,
                     std::string_view expected);
  // Returns the number of vertex references.
  std::size_t check_element_list(std::string_view keyword, std::string_view rest, int min_vertices);
  void check_vertex_reference(std::string_view reference);
  void check_index(std::string_view index_text, std::size_t defined, std::string_view element,
                   std::string_view reference);
  void add_material_use(std::string_view rest);
  void add_material_library(std::string_view rest);

  std::string_view file_;
  std::size_t line_ = 0;
  ObjTextSummary summary_;
  std::unordered_map<std::string, std::int32_t> used_names_;  // name -> index into materials_used
  std::int32_t current_material_ = -1;
};

void ObjTextValidator::check_line(std::string_view line, std::size_t line_number) {
  line_ = line_number;
  std::string_view rest = line;
  const std::string_view keyword = take_token(rest);
  if (keyword.empty() || keyword.front() == '#') return;
  // Ordered by how often they occur in real files.
  if (keyword == "v") {
    check_numbers(keyword, rest, 3, 7, "3 (x y z), 4 (x y z w) or 6 to 7 (x y z r g b)");
    ++summary_.position_count;
  } else if (keyword == "vt") {
    check_numbers(keyword, rest, 1, 3, "1 to 3 (u [v [w]])");
    ++summary_.texcoord_count;
  } else if (keyword == "vn") {
    check_numbers(keyword, rest, 3, 3, "3 (x y z)");
    ++summary_.normal_count;
  } else if (keyword == "f") {
    summary_.face_vertex_counts.push_back(static_cast<std::uint16_t>(check_element_list(keyword, rest, 3)));
    summary_.face_materials.push_back(current_material_);
  } else if (keyword == "l") {
    check_element_list(keyword, rest, 2);
  } else if (keyword == "p") {
    check_element_list(keyword, rest, 1);
  } else if (keyword == "usemtl") {
    add_material_use(rest);
  } else if (keyword == "mtllib") {
    add_material_library(rest);
  } else if (keyword == "s") {
    summary_.smoothing_groups = true;
  }
}

void ObjTextValidator::check_numbers(std::string_view keyword, std::string_view rest, int min_count, int max_count,
                                     std::string_view expected) {
  int count = 0;
  for (std::string_view token = take_token(rest); !token.empty(); token = take_token(rest)) {
    const std::optional<float> value = parse_float(token);
    if (!value) fail_here("'{}' line: '{}' is not a number", keyword, untrusted_text(token));
    if (!std::isfinite(*value)) fail_here("'{}' line: '{}' is not a finite number", keyword, untrusted_text(token));
    ++count;
  }
  if (count < min_count || count > max_count)
    fail_here("'{}' line has {} number{}, expected {}", keyword, count, count == 1 ? "" : "s", expected);
}

std::size_t ObjTextValidator::check_element_list(std::string_view keyword, std::string_view rest, int min_vertices) {
  std::size_t count = 0;
  for (std::string_view token = take_token(rest); !token.empty(); token = take_token(rest)) {
    // Triangulation is quadratic in a face's vertices (tinyobjloader's took seconds for a 20,000-vertex
    // face, minutes for 200,000): refuse large faces before anything is allocated for them.
    if (keyword == "f" && count == kMaxObjFaceVertices)
      fail_here("the face has more than {} vertices, glint's limit per face; triangulate the model (or split the "
                "polygon) when exporting it",
                kMaxObjFaceVertices);
    check_vertex_reference(token);
    ++count;
  }
  if (count < static_cast<std::size_t>(min_vertices))
    fail_here("'{}' line has {} vertex reference{}, at least {} needed", keyword, count, count == 1 ? "" : "s",
              min_vertices);
  return count;
}

void ObjTextValidator::check_vertex_reference(std::string_view reference) {
  // "v", "v/vt", "v//vn" or "v/vt/vn".
  std::string_view parts[3];
  int part_count = 0;
  std::string_view rest = reference;
  while (true) {
    if (part_count == 3) fail_here("'{}' is not a vertex reference (v, v/vt, v//vn or v/vt/vn)", untrusted_text(reference));
    const std::size_t slash = rest.find('/');
    parts[part_count++] = rest.substr(0, slash);
    if (slash == std::string_view::npos) break;
    rest.remove_prefix(slash + 1);
  }
  if (parts[0].empty()) fail_here("'{}' has no position index", untrusted_text(reference));
  check_index(parts[0], summary_.position_count, "position", reference);
  // The middle index may be empty only in "v//vn"; tinyobjloader would fail on "v/" without a line.
  if (part_count == 2 && parts[1].empty()) fail_here("'{}' has an empty texture coordinate index", untrusted_text(reference));
  if (part_count >= 2 && !parts[1].empty()) check_index(parts[1], summary_.texcoord_count, "texture coordinate", reference);
  if (part_count == 3) {
    if (parts[2].empty()) fail_here("'{}' has an empty normal index", untrusted_text(reference));
    check_index(parts[2], summary_.normal_count, "normal", reference);
  }
}

void ObjTextValidator::check_index(std::string_view index_text, std::size_t defined, std::string_view element,
                                   std::string_view reference) {
  const std::optional<long long> index = parse_integer(index_text);
  if (!index) fail_here("'{}': '{}' is not an integer index", untrusted_text(reference), untrusted_text(index_text));
  if (*index == 0) fail_here("'{}': index 0 is invalid (OBJ indices start at 1, or count back from -1)", untrusted_text(reference));
  const auto defined_count = static_cast<long long>(defined);
  if (*index > defined_count)
    fail_here("'{}': {} {} is out of range ({} defined before this line)", untrusted_text(reference), element, *index, defined);
  if (*index < -defined_count)
    fail_here("'{}': relative {} index {} is out of range ({} defined before this line)", untrusted_text(reference), element, *index,
              defined);
}

void ObjTextValidator::add_material_use(std::string_view rest) {
  // The whole rest of the line, as the MTL reader reads `newmtl`: names may hold blanks.
  const std::string_view name = obj_text::trim(rest);
  if (name.empty()) fail_here("'usemtl' needs a material name");
  const auto [it, inserted] = used_names_.try_emplace(std::string(name), static_cast<std::int32_t>(summary_.materials_used.size()));
  if (inserted) summary_.materials_used.push_back({std::string(name), line_});
  current_material_ = it->second;
}

void ObjTextValidator::add_material_library(std::string_view rest) {
  const std::string_view names = obj_text::trim(rest);
  if (names.empty()) fail_here("'mtllib' needs a file name");
  summary_.material_libraries.push_back({std::string(names), line_});
}

ObjTextSummary ObjTextValidator::finish() {
  if (summary_.face_vertex_counts.empty()) fail("{}: the file has no faces ('f' lines), so there is nothing to render", file_);
  return std::move(summary_);
}

}  // namespace

ObjTextSummary validate_obj_text(std::string_view text, std::string_view file_label) {
  // A NUL byte means a binary file (or a corrupt one); report it up front instead of as a strange
  // statement somewhere in the middle.
  if (const void* nul = std::memchr(text.data(), '\0', text.size()); nul != nullptr) {
    const auto offset = static_cast<std::size_t>(static_cast<const char*>(nul) - text.data());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
    fail("{}:{}: contains a NUL byte: this is not a text OBJ file", file_label, line);
  }
  ObjTextValidator validator(file_label);
  obj_text::LineReader lines(text);
  for (std::string_view line; lines.next(line);) validator.check_line(line, lines.line_number());
  return validator.finish();
}

}  // namespace glint
