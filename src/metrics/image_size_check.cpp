#include "metrics/image_size_check.h"

#include "core/error.h"

namespace glint::metrics {

template <typename Pixel>
void require_same_size(const Image<Pixel>& test, const Image<Pixel>& reference, std::string_view test_name,
                       std::string_view reference_name) {
  if (test.width != reference.width || test.height != reference.height)
    fail("cannot compare '{}' ({}x{}) with reference '{}' ({}x{}): the sizes differ", test_name, test.width,
         test.height, reference_name, reference.width, reference.height);
  if (test.width <= 0 || test.height <= 0)
    fail("cannot compare '{}' with reference '{}': the images are empty ({}x{})", test_name, reference_name,
         test.width, test.height);
}

// The pixel types the metrics use: 8-bit files, linear EXR colour and the double planes derived from them.
template void require_same_size(const Image<glm::u8vec4>&, const Image<glm::u8vec4>&, std::string_view,
                                std::string_view);
template void require_same_size(const Image<double>&, const Image<double>&, std::string_view, std::string_view);
template void require_same_size(const Image<glm::vec4>&, const Image<glm::vec4>&, std::string_view,
                                std::string_view);

}  // namespace glint::metrics
