#pragma once
// Input checks shared by the reflection passes (SSR, blur, resolve): a texture id handed to a pass
// must name a 2D texture of the format and size the pass was made for. Mismatches would otherwise
// show up as GL errors or silently wrong images, so they become glint::Errors naming the pass and
// the input ("ssr: input 'lit' is 32x32, the pass is 64x48").
#include <epoxy/gl.h>

namespace glint::render {

// Throws glint::Error when `texture` is 0, is not a texture, or its level 0 is not
// `width` x `height` of `internal_format`. Costs a few glGet queries (no GPU sync).
void require_texture(const char* pass, const char* input, GLuint texture, GLenum internal_format, int width,
                     int height);

// Throws glint::Error when `buffer` is 0 or not a buffer object.
void require_buffer(const char* pass, const char* input, GLuint buffer);

// Throws glint::Error for a non-positive size.
void require_pass_size(const char* pass, int width, int height);

}  // namespace glint::render
