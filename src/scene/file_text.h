#pragma once
// Reading a whole scene file (OBJ, MTL) into memory, with the errors a user can cause named.
#include <filesystem>
#include <string>

namespace glint {

// The file's bytes. Throws glint::Error "<path>: no such file" when it is missing, and
// "<path>: cannot read: <reason>" when it is a folder or cannot be opened or read.
std::string read_file_text(const std::filesystem::path& path);

}  // namespace glint
