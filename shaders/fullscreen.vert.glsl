#version 450 core
// One triangle that covers the whole viewport (no vertex buffer: positions come from gl_VertexID).
// Draw with glDrawArrays(GL_TRIANGLES, 0, 3) and any vertex array bound. The triangle's corners are
// (-1,-1), (3,-1), (-1,3); the part outside clip space is clipped away, leaving exactly the screen,
// and the single triangle avoids the diagonal seam a two-triangle quad would shade twice.
// uv is (0,0) at the bottom-left and (1,1) at the top-right, matching GL texture coordinates.

out vec2 uv;

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
  uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
