#pragma once
// `#include "name.glsl"` for GLSL, which has no include of its own. Pure text work (no GL), so it is
// tested without a context; ShaderProgram::from_embedded runs it over the embedded shaders.
//
// Rules: an include line is a line whose first token is #include (spaces allowed around the #),
// followed by one quoted name, optionally followed by a // comment. Names are relative to the
// shader root (shaders/), never to the including file. Each file is expanded at most once per stage
// (include-guard semantics): a later include of a file already expanded becomes a comment line.
// Includes are unconditional: the expander is line-based and does not see #if or block comments.
//
// Line mapping: each file gets a GLSL source-string number (0 for the top file, then in order of
// first inclusion) and the expanded text carries `#line <line> <number>` directives around every
// expanded include, so the driver's log names the file's number and its own line.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// The source of an include name, or nullopt when there is no such file.
using ShaderIncludeLookup = std::function<std::optional<std::string_view>(std::string_view name)>;

struct ExpandedShaderSource {
  std::string text;                // the complete source, includes replaced by their (expanded) text
  std::vector<std::string> files;  // files[n] = display name of GLSL source-string number n
};

// Include nesting deeper than this is an error (a cycle is reported as a cycle before that).
inline constexpr int kMaxShaderIncludeDepth = 16;

// Expands the includes of `source` (the file `name`). Display names in `files` and in errors are
// `display_root + name`, e.g. "shaders/" + "include/lighting.glsl". Throws glint::Error, naming the
// including file and line, for a malformed include line, an unknown include name, an include cycle,
// nesting deeper than kMaxShaderIncludeDepth, and an included file that declares #version.
ExpandedShaderSource expand_shader_includes(std::string_view name, std::string_view source,
                                            const ShaderIncludeLookup& lookup, std::string_view display_root = "");

// `source` with `#define <name> 1` for each of `defines` right after its #version line (GLSL allows
// nothing before it), then `#line 2 0`, so the driver still numbers the file's own lines. For the
// variants of one shader that differ in what the machine offers (an extension) and must say so
// before any declaration. Throws glint::Error when the first line is not #version or a name is not
// a GLSL identifier.
std::string add_shader_defines(std::string_view source, std::span<const std::string_view> defines);

}  // namespace glint
