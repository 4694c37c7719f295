#pragma once
// Linear float images as OpenEXR files (Debian's libopenexr-dev), the HDR companion of image.h's
// PNGs: `glint render --format exr` writes frames and debug views with them, `glint compare` reads
// them. Files hold three FLOAT (32-bit) channels R, G, B, ZIP-compressed (lossless), with the rows
// top first like every glint image; float rather than half so a file holds exactly what the GPU
// computed in 32-bit float (the round trip is exact) and debug views such as world positions and
// depths keep their precision (half has 11 bits: 6 cm steps at 100 m). String attributes carry what
// a reader needs to interpret the values (the renderer's tone map, render/tone_map.h).
#include "core/image.h"

#include <filesystem>
#include <map>
#include <string>

namespace glint {

// String attributes of an EXR header, by name.
using ExrText = std::map<std::string, std::string>;

struct ExrFile {
  ImageRgbaF image;  // rgb from the file's R, G, B channels, a = 1
  ExrText text;      // every string attribute of the header
};

// Writes `image`'s rgb (alpha is dropped) and `text` as string attributes. Encoded in memory, then
// written to a temporary file in the same folder and renamed (core/atomic_file.h), so a crash never
// leaves a half-written EXR under `path`. A missing or unwritable folder is a glint::Error naming it.
void write_exr(const std::filesystem::path& path, const ImageRgbaF& image, const ExrText& text = {});

// Reads an EXR's R, G and B channels (half, float or uint; converted to float). A missing file, a
// file that is not an EXR (checked by its magic number), a truncated or malformed one, one without R,
// G and B, or one over 2^28 pixels is one line naming the file (glint::Error).
ExrFile read_exr(const std::filesystem::path& path);

// Whether the file starts with OpenEXR's magic number (false when it cannot be read).
bool has_exr_signature(const std::filesystem::path& path);

}  // namespace glint
