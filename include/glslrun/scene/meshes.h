// The built-in meshes of scene files, and OBJ files. Each mesh carries
// gl_Vertex (xyz), gl_Normal and gl_MultiTexCoord0 (st), and is drawn as
// indexed GL_TRIANGLES unless stated otherwise. Geometry is computed in double
// precision and stored as float, so glslrun and the reference tool (Mesa) see
// bit-identical inputs.
#pragma once
#include <cstdint>
#include <string>

#include "glslrun/scene/scene.h"

namespace glslrun::scene {

// freeglut's glutSolidTeapot(size) geometry with `subdivisions` segments per
// patch edge (scene/teapot.cpp): 32 patches, (n+1)^2 vertices each.
Mesh make_teapot(double size, int subdivisions);
// The lecture's glBegin(GL_QUADS) quad: (-1,-1)..(1,1) at z = 0, normal +z,
// colours red, green, blue, yellow; drawn as GL_QUADS (split 0-1-2 / 0-2-3).
Mesh make_lecture_quad();
// Like glutSolidCube(size): 6 faces, 24 vertices, flat normals.
Mesh make_cube(double size);
// Like gluSphere / glutSolidSphere(radius, slices, stacks), z is the axis.
Mesh make_sphere(double radius, int slices, int stacks);
// Like glutSolidTorus(inner_radius, outer_radius, sides, rings), z is the axis.
Mesh make_torus(double inner_radius, double outer_radius, int sides, int rings);
// A square in the z = 0 plane, (-size/2..size/2), normal +z, split into
// subdivisions x subdivisions cells.
Mesh make_plane(double size, int subdivisions);
// Triangulated OBJ (tinyobjloader): positions, normals (computed per face when
// the file has none), texture coordinates. Errors cite the file and line.
Result<Mesh> load_obj(const std::string& path);
// gl_Color = 0.5 + 0.5 * normal, alpha 1 (the lecture's `colors` teapot).
void add_normal_colors(Mesh& mesh);

// Upper limits that keep a mesh's memory sane; the parser refuses larger.
constexpr int kMaxSubdivisions = 1024;
// The teapot's 32 patches have (n+1)^2 vertices each: 256 gives 2.1M vertices.
constexpr int kMaxTeapotSubdivisions = 256;
// All objects of a scene together (each mesh is counted once built, so a
// scene holds at most this plus one mesh): four of the largest teapots.
constexpr uint64_t kMaxSceneVertices = uint64_t(8) << 20;
// [[objects]] of a scene: each holds its own GL state (about 5 KB with its
// mesh's bookkeeping), so a 64 MiB scene of 2.8M quads would need 14 GB.
constexpr size_t kMaxSceneObjects = 65536;

}  // namespace glslrun::scene
