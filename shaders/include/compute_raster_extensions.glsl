// The compute rasteriser's extensions (ComputeVisibilityPass): include right after #version, before
// any declaration. GLINT_RASTER_ONE_ROUND (defined by the pass where the driver offers 64-bit
// atomics on storage buffers, GL_NV_shader_atomic_int64) keeps {depth, triangle} in one 64-bit word
// per pixel and needs one raster round instead of two 32-bit ones (compute_raster.glsl).
#extension GL_ARB_gpu_shader_int64 : require
#ifdef GLINT_RASTER_ONE_ROUND
#extension GL_NV_shader_atomic_int64 : require
#endif
