#include "viewer/picture_texture.h"

#include "core/error.h"

namespace glint::viewer {

void PictureTexture::ensure_size(int width, int height) {
  if (texture_ && width == width_ && height == height_) return;
  texture_ = create_texture_2d(GL_RGBA8, width, height);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  width_ = width;
  height_ = height;
}

void PictureTexture::copy_from(GLuint source, int width, int height) {
  if (source == 0) fail("view: no rendered image to show");
  ensure_size(width, height);
  glCopyImageSubData(source, GL_TEXTURE_2D, 0, 0, 0, 0, texture_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
  bottom_row_first_ = true;
}

void PictureTexture::upload(const ImageRgba8& image) {
  ensure_size(image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.pixels.data());
  bottom_row_first_ = false;
}

}  // namespace glint::viewer
