#pragma once
// Strict, located access to a parsed JSON document for glint's own file formats. Every value carries
// the file it came from and its JSON pointer, so every complaint reads
// "scene.json: /meshes/2/transform/scale: expected a number or [x, y, z], got string".
// Internal to the scene module (it exposes nlohmann::json, which the public headers do not).
#include "core/error.h"
#include "core/math.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

class JsonField {
public:
  JsonField(const nlohmann::json& value, std::string file_label, std::string pointer);

  const nlohmann::json& json() const { return *value_; }
  const std::string& pointer() const { return pointer_; }      // "" for the root, else "/a/0/b"
  std::string location() const;                                // "<file>: <pointer or />"

  // Throws a glint::Error "<file>: <pointer>: <message>".
  template <typename... Args>
  [[noreturn]] void error(fmt::format_string<Args...> format, Args&&... args) const {
    fail("{}: {}", location(), fmt::format(format, std::forward<Args>(args)...));
  }

  // Objects. require_object() also rejects every key not in `allowed` (unknown keys are typos).
  void require_object(std::initializer_list<std::string_view> allowed) const;
  std::optional<JsonField> find(std::string_view key) const;
  JsonField at(std::string_view key) const;                    // missing: "missing required key"

  // Arrays.
  std::vector<JsonField> elements() const;

  // Scalars; numbers must be finite.
  float number() const;
  float number_in(float lo, float hi) const;                   // inclusive range
  int integer() const;                                         // a whole number within int range
  std::string string() const;
  vec3 vec3_value() const;                                     // [x, y, z]
  std::vector<vec3> points() const;                            // [[x, y, z], ...]

private:
  JsonField child(const nlohmann::json& value, std::string_view key) const;
  const nlohmann::json* value_;
  std::string file_label_;
  std::string pointer_;
};

// The JSON type's name as a user would say it ("number", "string", "array", ...).
std::string_view json_type_name(const nlohmann::json& value);

// Parses JSON text (comments allowed); a syntax error becomes
// "<file>:<line>:<column>: malformed JSON: <what>".
nlohmann::json parse_json_text(std::string_view text, const std::string& file_label);

// 1-based line and column of the byte at `offset` (0-based) in `text`.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};
TextPosition text_position(std::string_view text, std::size_t offset);

}  // namespace glint
