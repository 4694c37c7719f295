#pragma once
// One way to name an enum: a constexpr table of {value, name} pairs per enum, with the lookups every
// named enum needs (the name of a value, the value of a name with a glint::Error listing the known
// names, the names for a CLI11 IsMember check), so each name is written once, in its enum's header.
//
//   inline constexpr EnumNames<UpdatePolicy, 3> kUpdatePolicyNames{
//       "update policy", {{UpdatePolicy::rebuild, "rebuild"}, {UpdatePolicy::refit, "refit"},
//                         {UpdatePolicy::automatic, "auto"}}};
//   kUpdatePolicyNames.name_of(UpdatePolicy::refit) == "refit"
//   kUpdatePolicyNames.parse("sometimes")  -> unknown update policy "sometimes" (known: rebuild, refit, auto)
//   ->check(CLI::IsMember(kUpdatePolicyNames.names()))
// Header-only and free of fmt: glint_accel and .cu files (through cuda/trace_kernel.h) include it.
#include "core/error_type.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

template <typename Enum, std::size_t N>
struct EnumNames {
  struct Entry {
    Enum value;
    std::string_view name;
  };

  std::string_view what;  // the noun of the messages: "update policy", "BVH builder"
  Entry entries[N];       // in the order lists and messages give them

  // The name of `value`; "?" for a value the table lacks (a cast integer).
  constexpr std::string_view name_of(Enum value) const {
    for (const Entry& entry : entries)
      if (entry.value == value) return entry.name;
    return "?";
  }

  constexpr std::optional<Enum> find(std::string_view name) const {
    for (const Entry& entry : entries)
      if (entry.name == name) return entry.value;
    return std::nullopt;
  }

  constexpr bool contains(std::string_view name) const { return find(name).has_value(); }

  // The value named `name`; glint::Error `unknown <what> "<name>" (known: a, b, c)` otherwise.
  Enum parse(std::string_view name) const {
    if (const std::optional<Enum> value = find(name)) return *value;
    throw Error("unknown " + std::string(what) + " \"" + std::string(name) + "\" (known: " + joined() + ")");
  }

  // Every value, in table order.
  constexpr std::array<Enum, N> values() const {
    std::array<Enum, N> values{};
    for (std::size_t i = 0; i < N; ++i) values[i] = entries[i].value;
    return values;
  }

  // Every name, in table order: the choices of a CLI11 IsMember check.
  std::vector<std::string> names() const {
    std::vector<std::string> names;
    names.reserve(N);
    for (const Entry& entry : entries) names.emplace_back(entry.name);
    return names;
  }

  // "a, b, c" (help texts and messages).
  std::string joined(std::string_view separator = ", ") const {
    std::string text;
    for (const Entry& entry : entries) {
      if (!text.empty()) text += separator;
      text += entry.name;
    }
    return text;
  }
};

}  // namespace glint
