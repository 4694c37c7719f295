#pragma once
// Every metric compares two images pixel by pixel, so both must have the same size; the check lives
// in one place so that the error always names both sizes and both images.
#include "core/image.h"

#include <string_view>

namespace glint::metrics {

// Names used in error messages when a caller has no file names (library use).
inline constexpr std::string_view kDefaultTestName = "test image";
inline constexpr std::string_view kDefaultReferenceName = "reference image";

// Throws a glint::Error "cannot compare 'a.png' (640x480) with reference 'b.png' (320x240): the
// sizes differ" unless both images have the same width and height. Empty images are errors too.
template <typename Pixel>
void require_same_size(const Image<Pixel>& test, const Image<Pixel>& reference,
                       std::string_view test_name = kDefaultTestName,
                       std::string_view reference_name = kDefaultReferenceName);

}  // namespace glint::metrics
