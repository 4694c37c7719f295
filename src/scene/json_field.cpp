#include "scene/json_field.h"

#include "core/untrusted_text.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <set>
#include <vector>

namespace glint {
namespace {

// JSON pointer escaping (RFC 6901): '~' -> "~0", '/' -> "~1".
std::string escape_pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string join_keys(std::initializer_list<std::string_view> keys) {
  std::string out;
  for (std::string_view key : keys) {
    if (!out.empty()) out += ", ";
    out += key;
  }
  return out;
}

}  // namespace

JsonField::JsonField(const nlohmann::json& value, std::string file_label, std::string pointer)
    : value_(&value), file_label_(std::move(file_label)), pointer_(std::move(pointer)) {}

// The pointer is made of the file's keys, so it is shown bounded and escaped.
std::string JsonField::location() const {
  return fmt::format("{}: {}", file_label_, pointer_.empty() ? "/" : untrusted_text(pointer_));
}

JsonField JsonField::child(const nlohmann::json& value, std::string_view key) const {
  return JsonField(value, file_label_, pointer_ + "/" + escape_pointer_token(key));
}

void JsonField::require_object(std::initializer_list<std::string_view> allowed) const {
  if (!value_->is_object()) error("expected an object, got {}", json_type_name(*value_));
  for (const auto& item : value_->items()) {
    const bool known = std::find(allowed.begin(), allowed.end(), std::string_view(item.key())) != allowed.end();
    if (!known) child(item.value(), item.key()).error("unknown key (expected one of: {})", join_keys(allowed));
  }
}

std::optional<JsonField> JsonField::find(std::string_view key) const {
  if (!value_->is_object()) error("expected an object, got {}", json_type_name(*value_));
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return child(*it, key);
}

JsonField JsonField::at(std::string_view key) const {
  std::optional<JsonField> field = find(key);
  if (!field) error("missing required key \"{}\"", key);
  return *field;
}

std::vector<JsonField> JsonField::elements() const {
  if (!value_->is_array()) error("expected an array, got {}", json_type_name(*value_));
  std::vector<JsonField> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) out.push_back(child((*value_)[i], std::to_string(i)));
  return out;
}

float JsonField::number() const {
  if (!value_->is_number()) error("expected a number, got {}", json_type_name(*value_));
  const double value = value_->get<double>();
  // JSON has no NaN/inf literals, but an overflowing literal such as 1e999 parses to inf, and a
  // double that does not fit a float becomes inf on conversion.
  if (!std::isfinite(value) || std::abs(value) > static_cast<double>(std::numeric_limits<float>::max()))
    error("expected a finite number, got {}", value_->dump());
  return static_cast<float>(value);
}

float JsonField::number_in(float lo, float hi) const {
  const float value = number();
  if (value < lo || value > hi) error("{} is out of range (expected {} to {})", value_->dump(), lo, hi);
  return value;
}

int JsonField::integer() const {
  if (!value_->is_number()) error("expected a whole number, got {}", json_type_name(*value_));
  const double value = value_->get<double>();
  if (!std::isfinite(value) || value != std::floor(value) || value < std::numeric_limits<int>::min() ||
      value > std::numeric_limits<int>::max())
    error("expected a whole number, got {}", value_->dump());
  return static_cast<int>(value);
}

std::string JsonField::string() const {
  if (!value_->is_string()) error("expected a string, got {}", json_type_name(*value_));
  return value_->get<std::string>();
}

vec3 JsonField::vec3_value() const {
  if (!value_->is_array() || value_->size() != 3)
    error("expected [x, y, z], got {}", value_->is_array() ? fmt::format("an array of {}", value_->size())
                                                           : std::string(json_type_name(*value_)));
  const std::vector<JsonField> items = elements();
  return vec3(items[0].number(), items[1].number(), items[2].number());
}

std::vector<vec3> JsonField::points() const {
  std::vector<vec3> out;
  for (const JsonField& item : elements()) out.push_back(item.vec3_value());
  return out;
}

std::string_view json_type_name(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "object";
    case nlohmann::json::value_t::array: return "array";
    case nlohmann::json::value_t::string: return "string";
    case nlohmann::json::value_t::boolean: return "boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "number";
    default: return "unknown";
  }
}

TextPosition text_position(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  TextPosition position;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset; ++i)
    if (text[i] == '\n') {
      ++position.line;
      line_start = i + 1;
    }
  position.column = offset - line_start + 1;
  return position;
}

namespace {

// A character iterator over the text that records, in `read`, how far the parser has read: the
// parser callback is told only what it parsed, not where, and duplicate keys are reported by line.
struct TrackingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* at = nullptr;
  std::size_t* read = nullptr;

  reference operator*() const { return *at; }
  TrackingIterator& operator++() {
    ++at;
    ++*read;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const TrackingIterator& other) const { return at == other.at; }
};

// Where the key that ends just before `end` (the byte after its closing quote) starts: its opening
// quote, the first '"' before the closing one that is not escaped.
std::size_t key_start(std::string_view text, std::size_t end) {
  if (end < 2) return 0;
  for (std::size_t i = end - 1; i-- > 0;) {
    if (text[i] != '"') continue;
    std::size_t backslashes = 0;
    while (i > backslashes && text[i - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return 0;
}

}  // namespace

nlohmann::json parse_json_text(std::string_view text, const std::string& file_label) {
  // JSON allows repeated keys and nlohmann keeps the last; in glint's files a repeated key is a
  // mistake (the first value would be silently ignored), so the parser callback refuses it.
  std::size_t read = 0;
  std::vector<std::set<std::string>> open_objects;  // the keys seen so far in each enclosing object
  const auto on_event = [&](int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open_objects.emplace_back();
    else if (event == Event::object_end && !open_objects.empty()) open_objects.pop_back();
    else if (event == Event::key && !open_objects.empty()) {
      const std::string& key = parsed.get_ref<const std::string&>();
      if (!open_objects.back().insert(key).second) {
        const TextPosition at = text_position(text, key_start(text, read));
        fail("{}:{}:{}: duplicate key \"{}\" (each key may appear once per object)", file_label, at.line, at.column,
             untrusted_text(key));
      }
    }
    return true;
  };
  const TrackingIterator first{text.data(), &read};
  const TrackingIterator last{text.data() + text.size(), &read};
  try {
    return nlohmann::json::parse(first, last, on_event, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based index of the last character read, i.e. where the parser gave up.
    const TextPosition at = text_position(text, e.byte > 0 ? e.byte - 1 : 0);
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: <what>";
    // keep only <what>, since the position is reported in the file:line:column form.
    std::string what = e.what();
    const std::size_t column = what.find(", column ");
    const std::size_t colon = column == std::string::npos ? std::string::npos : what.find(": ", column);
    if (colon != std::string::npos) what = what.substr(colon + 2);
    fail("{}:{}:{}: malformed JSON: {}", file_label, at.line, at.column, untrusted_text(what));  // quotes what it read
  } catch (const nlohmann::json::out_of_range& e) {
    // A number too large for a double ("number overflow parsing '1e999'") carries no position; find
    // the quoted literal in the text instead.
    std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    const std::size_t open = what.find('\'');
    const std::size_t close = open == std::string::npos ? std::string::npos : what.find('\'', open + 1);
    const std::size_t at = close == std::string::npos ? std::string_view::npos
                                                      : text.find(what.substr(open + 1, close - open - 1));
    if (at == std::string_view::npos) fail("{}: malformed JSON: {}", file_label, untrusted_text(what));
    const TextPosition position = text_position(text, at);
    fail("{}:{}:{}: malformed JSON: {}", file_label, position.line, position.column, untrusted_text(what));
  } catch (const nlohmann::json::exception& e) {
    fail("{}: malformed JSON: {}", file_label, untrusted_text(e.what()));
  }
}

}  // namespace glint
