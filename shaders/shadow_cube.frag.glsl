#version 450 core
// Shadow cube map: depth only. The rasteriser writes the depth (near / distance along the face's
// axis, ShadowCubePass); writing gl_FragDepth here would turn off the early depth test.

void main() {}
