#pragma once
// Tiny scenes built in code for the raster tests, and the CPU geometry the tests compare against.
#include "core/image.h"
#include "core/math.h"
#include "render/frame_constants.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <optional>
#include <vector>

namespace glint::testing {

// A scene with no geometry yet, a valid walkthrough, the light at `light` (range 10, intensity 20).
Scene make_empty_test_scene(vec3 light);

// Adds a material and returns its index.
std::uint32_t add_material(Scene& scene, vec3 diffuse, float reflectivity = 0.0f, int texture = -1);

// Adds a parallelogram origin + s * edge_u + t * edge_v (s, t in 0..1) as its own mesh and
// instance: normal cross(edge_u, edge_v) normalised, uv = (s, t), counter-clockwise seen from the
// normal's side. Returns the mesh index.
std::uint32_t add_quad(Scene& scene, vec3 origin, vec3 edge_u, vec3 edge_v, std::uint32_t material);

// The camera at `eye` looking at `target` (60 degrees vertical), light at `light`.
FrameState look_at(vec3 eye, vec3 target, vec3 light);

// World-space direction of the ray through the centre of pixel (x, y), y counted from the top.
vec3 pixel_ray(const render::FrameConstants& constants, int x, int y);

// Where the ray from `origin` along `direction` meets the quad, if it does (t > 0).
std::optional<vec3> hit_quad(vec3 origin, vec3 direction, vec3 quad_origin, vec3 edge_u, vec3 edge_v);

// A mirror floor (reflectivity 1, dark grey, 40 x 40 around the origin) and an emissive red wall
// (`wall_size` wide and high, centred on x = 0) standing on it at z = `wall_z`, facing +z. camera_looking_down_the_floor() at (0, 1.5, 6) looks towards -z,
// slightly down, so a wall at z = -4 is in view and its mirror image lies on the floor below it; a
// wall at z = 10 is behind the camera, and only rays can find its reflection.
Scene mirror_floor_with_wall(float wall_z, vec2 wall_size = vec2(6.0f, 2.0f));
FrameState camera_looking_down_the_floor();

// A strip of mirror floor (1 wide) in the middle of the view, ending before a wide lit wall that
// fills the view beyond it (light at (0, 3, 2)): seen from (0, 1, 6) looking towards -z, every
// reflected ray meets the wall well inside the screen, so SSR finds them all.
Scene mirror_strip_before_wall();

// A mirror floor and an emissive red ceiling (y = 4, z from 2 to 8) over the camera of
// camera_looking_steeply_down(), at (0, 1.5, 6) looking 60 degrees down: the whole ceiling lies
// behind the camera's image plane, yet the floor under the camera mirrors it, so SSR fails on every
// reflective pixel and only rays find the ceiling.
Scene mirror_floor_under_ceiling();
FrameState camera_looking_steeply_down();

struct QuadGeometry {
  vec3 origin, edge_u, edge_v;
};

// A 40 x 40 floor (y = 0, material 0, normal up) lit from (0, 4, 0), with two occluders:
// a 2 x 2 horizontal quad at y = 2 over the origin (material 1, emissive) and a 3 wide, 1 high wall
// standing on the floor at x = 3 facing the light (material 2). `occluders` receives their geometry.
Scene make_floor_with_occluders(std::vector<QuadGeometry>& occluders);

// Whether the segment from `point` to `light` crosses any of `quads`.
bool light_blocked(vec3 point, vec3 light, const std::vector<QuadGeometry>& quads);

}  // namespace glint::testing
