#pragma once
// Reading a whole scene file (OBJ, MTL) into memory, with the errors a user can cause named.
#include <filesystem>
#include <string>

namespace glint {

// The file's bytes, less a UTF-8 byte order mark at its start (Windows editors and some exporters
// write one; left in, it glued itself to the first statement: an OBJ lost its first vertex and an MTL
// its first `newmtl`). Throws glint::Error "<path>: no such file" when it is missing, and
// "<path>: cannot read: <reason>" when it is a folder or cannot be opened or read.
std::string read_file_text(const std::filesystem::path& path);

}  // namespace glint
