#include "core/exr_image.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <array>
#include <exception>
#include <fstream>
#include <string_view>
#include <system_error>

namespace glint {
namespace {

constexpr std::array<const char*, 3> kChannels = {"R", "G", "B"};
constexpr long long kMaxPixels = 1LL << 28;  // a corrupt header must not ask for terabytes

// OpenEXR's messages may span lines; an error is one line.
std::string one_line(std::string_view text) {
  std::string line(text);
  std::replace(line.begin(), line.end(), '\n', ' ');
  return line;
}

// The slices of R, G, B inside `pixels` (vec4 rows of `width`), for a data window starting at
// (min_x, min_y): OpenEXR addresses pixel (x, y) at base + x * xStride + y * yStride.
Imf::FrameBuffer rgb_slices(char* pixels, int width, int min_x, int min_y) {
  const std::size_t x_stride = sizeof(glm::vec4), y_stride = x_stride * static_cast<std::size_t>(width);
  char* base = pixels - static_cast<std::ptrdiff_t>(min_x) * static_cast<std::ptrdiff_t>(x_stride) -
               static_cast<std::ptrdiff_t>(min_y) * static_cast<std::ptrdiff_t>(y_stride);
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < kChannels.size(); ++c)
    frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), x_stride, y_stride));
  return frame;
}

}  // namespace

void write_exr(const std::filesystem::path& path, const ImageRgbaF& image, const ExrText& text) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    fail("cannot write EXR '{}': image is {}x{} with {} pixels", path.string(), image.width, image.height,
         image.pixels.size());
  std::string encoded;
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* channel : kChannels) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    for (const auto& [name, value] : text) header.insert(name, Imf::StringAttribute(value));
    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);
      // OpenEXR only reads through the slices; its API takes char*.
      file.setFrameBuffer(rgb_slices(const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data())),
                                     image.width, 0, 0));
      file.writePixels(image.height);
    }  // the file's destructor completes the stream (offset table)
    encoded = stream.str();
  } catch (const std::exception& error) {
    fail("cannot write EXR '{}': {}", path.string(), one_line(error.what()));
  }
  // Encoded in memory first, so the file on disk is either the whole EXR or nothing (temp + rename).
  write_file_atomically(path, encoded);
}

bool has_exr_signature(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::array<char, 4> head{};
  file.read(head.data(), head.size());
  return file.gcount() == static_cast<std::streamsize>(head.size()) && Imf::isImfMagic(head.data());
}

ExrFile read_exr(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail("cannot read EXR '{}': no such file", path.string());
  if (std::filesystem::is_directory(path, error)) fail("cannot read EXR '{}': is a directory", path.string());
  if (!std::ifstream(path, std::ios::binary)) fail("cannot read EXR '{}': cannot open it", path.string());
  if (!has_exr_signature(path)) fail("cannot read EXR '{}': not an EXR file", path.string());
  ExrFile result;
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    for (const char* channel : kChannels)
      if (header.channels().findChannel(channel) == nullptr)
        fail("cannot read EXR '{}': it has no {} channel (glint reads R, G and B)", path.string(), channel);
    const Imath::Box2i window = header.dataWindow();
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0 || width * height > kMaxPixels)
      fail("cannot read EXR '{}': data window of {}x{} pixels (1 to 2^28 pixels are read)", path.string(), width,
           height);
    result.image = ImageRgbaF(static_cast<int>(width), static_cast<int>(height), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    file.setFrameBuffer(rgb_slices(reinterpret_cast<char*>(result.image.pixels.data()), static_cast<int>(width),
                                   window.min.x, window.min.y));
    file.readPixels(window.min.y, window.max.y);
    for (auto it = header.begin(); it != header.end(); ++it)
      if (const auto* string = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        result.text[it.name()] = string->value();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& exception) {
    fail("cannot read EXR '{}': {}", path.string(), one_line(exception.what()));
  }
  return result;
}

}  // namespace glint
