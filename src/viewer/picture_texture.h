#pragma once
// The texture the viewer shows behind its panels. The final image is copied into it on the GPU from
// the pipeline's own texture (same context, glCopyImageSubData: no read back to the host, no upload),
// so a frame on the screen costs no host round trip; pictures made on the host (debug views, the
// difference heat map) are uploaded. The copy keeps its own texture, so the picture stays valid
// when the pipeline that made it is rebuilt or fails to build.
#include "core/image.h"
#include "gl/gl_objects.h"

#include <epoxy/gl.h>

namespace glint::viewer {

class PictureTexture {
public:
  // Copies `source` (RGBA8, the pipeline's final image: rows bottom first, as GL keeps them).
  void copy_from(GLuint source, int width, int height);
  // Uploads `image` (rows top first, as ImageRgba8 keeps them).
  void upload(const ImageRgba8& image);

  GLuint id() const { return texture_.id(); }  // 0 before the first picture
  int width() const { return width_; }
  int height() const { return height_; }
  // Whether texture row 0 is the picture's bottom row (a GPU copy) rather than its top (an upload):
  // how the picture is drawn upright.
  bool bottom_row_first() const { return bottom_row_first_; }

private:
  void ensure_size(int width, int height);

  GlTexture texture_;
  int width_ = 0;
  int height_ = 0;
  bool bottom_row_first_ = false;
};

}  // namespace glint::viewer
