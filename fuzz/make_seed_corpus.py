#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora, fuzz/corpus/<target>/, from the inputs of the loaders' tests
(tests/scene/obj_loader_test.cpp, mtl_reader_test.cpp, gltf_loader_test.cpp, scene_json_test.cpp,
scene_json_obj_test.cpp, texture_io_test.cpp) and a few small files covering the formats' variants.
Run once from the repository root; the result is committed (docs/reliability.md, "Fuzzing").
JPEG and GIF seeds need ffmpeg (scripts/setup.sh installs it)."""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
MTL_SEPARATOR = "\n=mtl=\n"  # kObjMtlSeparator in fuzz/fuzz_entries.h


def write(target, name, data):
    folder = os.path.join(ROOT, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# --- OBJ + MTL (the OBJ is loaded as f.obj, the MTL part as f.mtl) -------------------------------------
CUBE_OBJ = """# test cube
mtllib f.mtl
o cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
vn 0 0 1
vn -1 0 0
vn 1 0 0
vn 0 -1 0
vn 0 1 0
usemtl red
f 1/1/1 4/2/1 3/3/1 2/4/1
f 5/1/2 6/2/2 7/3/2 8/4/2
f 1/1/3 5/2/3 8/3/3 4/4/3
f 2/1/4 3/2/4 7/3/4 6/4/4
usemtl mirror
f 1/1/5 2/2/5 6/3/5 5/4/5
f 4/1/6 8/2/6 7/3/6 3/4/6
"""
CUBE_MTL = """newmtl red
Kd 0.8 0.1 0.1
Ks 0.5 0.5 0.5
Ns 64
map_Kd red.png

newmtl mirror
Kd 0.9
Ks 0 0 0
Pm 0.75
Ke 0.1 0.2 0.3
"""
BARE_CUBE = """v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 4 3 2
f 5 6 7 8
f 1 5 8 4
f 2 3 7 6
f 1 2 6 5
f 4 8 7 3
"""
TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"


def obj_seeds():
    write("obj_mtl", "cube_with_mtl", CUBE_OBJ + MTL_SEPARATOR + CUBE_MTL)
    write("obj_mtl", "cube_missing_mtl", CUBE_OBJ)
    write("obj_mtl", "bare_cube", BARE_CUBE)
    write("obj_mtl", "uv_winding", TRI + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf -3/-3 -1/-1 -2/-2\n")
    write("obj_mtl", "two_materials",
          "mtllib f.mtl\no a\nusemtl a\n" + TRI + "f 1 2 3\ng b\nusemtl b\nv 1 1 0\nf 2 4 3\n"
          + MTL_SEPARATOR + "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n")
    write("obj_mtl", "texture_options",
          "mtllib f.mtl\nusemtl wall\n" + TRI + "f 1 2 3\n"
          + MTL_SEPARATOR + "newmtl wall\nmap_Kd -s 1 1 1 -o 0 0 0 tex\\WALL.PNG\nNs 10\nd 0.5\nillum 2\n")
    write("obj_mtl", "late_mtllib", "usemtl wall\n" + TRI + "f 1 2 3\nmtllib f.mtl\n"
          + MTL_SEPARATOR + "newmtl wall\nKd 0 0 1\n")
    write("obj_mtl", "bad_number", "mtllib f.mtl\nusemtl wall\n" + TRI + "f 1 2 3\n"
          + MTL_SEPARATOR + "newmtl wall\n\nKd 0.5 abc 1\n")
    write("obj_mtl", "statement_before_newmtl", "mtllib f.mtl\n" + TRI + "f 1 2 3\n"
          + MTL_SEPARATOR + "# header\nNs 10\nnewmtl wall\n")
    write("obj_mtl", "flat_mixed", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.25\nvn 0 0 1\n"
          "s off\nf 1/1/1 2/1/1 3/1/1\ns 1\nf 2//1 4//1 3//1\nl 1 2\np 3\n")
    write("obj_mtl", "polygon_and_degenerate", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\n"
          "f 1 2 3 5 4\nf 1 1 2\nf 1 2 3 \\\n 4\n")
    write("obj_mtl", "index_out_of_range", TRI + "f 1 2 9\n")
    # An L-shaped face from its reflex corner, a relative-index quad, a bridged hole, smoothing groups.
    write("obj_mtl", "concave_polygons_smoothing",
          "v 0 0 0\nv 1 0 0\nv 1 0 -3\nv 4 0 -3\nv 4 0 -4\nv 0 0 -4\ns off\nf 3 4 5 6 1 2\n"
          "v 0 0 -4\nv 4 0 -4\nv 4 2 -4\nv 0 2 -4\ns 1\nf -4 -3 -2 -1\nf 1 2 3 4 8 7 6 5 8 4\n")
    # Byte order marks and paths from the author's Windows machine.
    write("obj_mtl", "byte_order_marks_windows_paths",
          "\ufeffmtllib C:\\model\\f.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nusemtl a\ns 2\n"
          "f 1/1 2/1 3/1 4/1" + MTL_SEPARATOR + "\ufeffnewmtl a\nmap_Kd D:\\textures\\w.png\n")
    write("obj_mtl", "crlf_comments", "# crlf\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0 1.0\r\nf 1 2 3\r\n")


# --- glTF / GLB -----------------------------------------------------------------------------------------
class Gltf:
    """Like tests/scene/gltf_test_builder: one buffer, a view and an accessor per array."""

    def __init__(self):
        self.bin = b""
        self.doc = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": []}

    def view(self, data):
        self.bin += b"\0" * (-len(self.bin) % 4)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, fmt, values, component_type, kind, per):
        v = self.view(struct.pack("<%d%s" % (len(values), fmt), *values))
        self.doc["accessors"].append({"bufferView": v, "componentType": component_type,
                                      "count": len(values) // per, "type": kind})
        return len(self.doc["accessors"]) - 1

    def vec3(self, xyz):
        a = self.accessor("f", xyz, 5126, "VEC3", 3)
        if xyz:
            self.doc["accessors"][a]["min"] = [min(xyz[i::3]) for i in range(3)]
            self.doc["accessors"][a]["max"] = [max(xyz[i::3]) for i in range(3)]
        return a

    def vec2(self, st):
        return self.accessor("f", st, 5126, "VEC2", 2)

    def indices(self, values, fmt="H", component_type=5123):
        return self.accessor(fmt, values, component_type, "SCALAR", 1)

    def mesh_node(self, primitive, **node):
        self.doc.setdefault("meshes", []).append({"primitives": [primitive]})
        self.doc.setdefault("nodes", []).append(dict(node, mesh=len(self.doc["meshes"]) - 1))
        return len(self.doc["nodes"]) - 1

    def with_buffer(self, buffer):
        doc = dict(self.doc)
        doc["buffers"] = [dict(buffer, byteLength=len(self.bin))]
        return doc

    def gltf(self):
        uri = "data:application/octet-stream;base64," + base64.b64encode(self.bin).decode()
        return json.dumps(self.with_buffer({"uri": uri}), separators=(",", ":"))

    def glb(self):
        text = json.dumps(self.with_buffer({}), separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        data = self.bin + b"\0" * (-len(self.bin) % 4)
        chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


UNIT_TRIANGLE = [0, 0, 0, 1, 0, 0, 0, 1, 0]
QUAD = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]


def gltf_seeds():
    g = Gltf()
    g.mesh_node({"attributes": {"POSITION": g.vec3(UNIT_TRIANGLE)}, "indices": g.indices([0, 1, 2])})
    write("gltf", "triangle_u16.gltf", g.gltf())
    write("gltf", "triangle_u16.glb", g.glb())

    g = Gltf()
    g.mesh_node({"attributes": {"POSITION": g.vec3(QUAD)}, "indices": g.indices([0, 1, 2, 0, 2, 3], "B", 5121)})
    g.mesh_node({"attributes": {"POSITION": g.vec3(QUAD)}, "indices": g.indices([0, 1, 2, 0, 2, 3], "I", 5125)},
                translation=[2, 0, 0], rotation=[0, 0.7071068, 0, 0.7071068], scale=[1, 2, 1])
    g.doc["nodes"].append({"children": [0, 1], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]})
    g.doc["scenes"] = [{"nodes": [2]}]
    g.doc["scene"] = 0
    write("gltf", "hierarchy_u8_u32.gltf", g.gltf())

    g = Gltf()
    g.mesh_node({"attributes": {"POSITION": g.vec3(QUAD)}, "indices": g.indices([0, 1, 3, 2]), "mode": 5})
    g.mesh_node({"attributes": {"POSITION": g.vec3(QUAD)}, "mode": 6})
    g.mesh_node({"attributes": {"POSITION": g.vec3(QUAD)}, "mode": 1})
    write("gltf", "strip_fan_lines.gltf", g.gltf())

    # Normals, UVs and a material whose base colour texture is a PNG in the buffer.
    g = Gltf()
    image_view = g.view(png_rgba(2, 2, bytes([255, 0, 0, 255] * 4)))
    g.doc["images"] = [{"bufferView": image_view, "mimeType": "image/png"}]
    g.doc["textures"] = [{"source": 0}]
    g.doc["materials"] = [{"name": "ground", "pbrMetallicRoughness": {
        "baseColorFactor": [1, 0.5, 0.25, 1], "metallicFactor": 1, "roughnessFactor": 0.2,
        "baseColorTexture": {"index": 0}}, "emissiveFactor": [0.1, 0, 0]}]
    g.mesh_node({"attributes": {"POSITION": g.vec3(UNIT_TRIANGLE), "NORMAL": g.vec3([0, 0, 1] * 3),
                                "TEXCOORD_0": g.vec2([0, 0, 1, 0, 0, 1])}, "indices": g.indices([0, 1, 2]),
                 "material": 0})
    write("gltf", "textured_material.glb", g.glb())

    g = Gltf()
    g.doc["images"] = [{"uri": "missing.png"}]
    g.doc["textures"] = [{"source": 0}]
    g.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    g.mesh_node({"attributes": {"POSITION": g.vec3(UNIT_TRIANGLE)}, "material": 0})
    write("gltf", "missing_image.gltf", g.gltf())

    g = Gltf()
    g.mesh_node({"attributes": {"POSITION": g.vec3(UNIT_TRIANGLE)}, "indices": g.indices([0, 1, 2])})
    g.doc["accessors"][0]["byteOffset"] = 4
    g.doc["bufferViews"][0]["byteStride"] = 16
    g.doc["accessors"][1]["sparse"] = {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                                       "values": {"bufferView": 1}}
    write("gltf", "stride_sparse.gltf", g.gltf())

    g = Gltf()
    g.mesh_node({"attributes": {"POSITION": g.vec3(UNIT_TRIANGLE)}})
    g.doc["accessors"][0]["count"] = 4
    g.doc["nodes"].append({"children": [0, 0]})
    g.doc["nodes"].append({"children": [1, 1]})
    write("gltf", "overlong_accessor_shared_children.gltf", g.gltf())


# --- scene JSON (placing the scratch folder's m.obj and m.gltf, fuzz/fuzz_entries.cpp) ------------------
def scene_json_seeds():
    write("scene_json", "complete", """{
  "name": "gallery",
  "frames": 120, "fps": 24, "sky_color": [0.55, 0.65, 0.8],
  "meshes": [
    { "file": "m.obj", "name": "atrium" },
    { "file": "m.gltf", "name": "nemo",
      "transform": { "translate": [-7.0, 1.234, -0.5], "rotate": [0, 90, 0], "scale": 2.0 },
      "material": { "diffuse": [0.7, 0.6, 0.5], "reflectivity": 0.2, "specular_exponent": 64,
                    "specular": [1, 1, 1], "roughness": 0.5, "emissive": [0, 0, 0] } },
    { "file": "m.obj", "name": "spot", "transform": { "scale": [1, 2, 3] },
      "deform": { "type": "sine", "axis": "z", "along": "y", "amplitude": 0.05, "frequency": 5.0, "speed": 2.0 } }
  ],
  "floor": { "materials": ["red"], "reflectivity": 0.5 },
  "light": { "color": [1.0, 0.95, 0.85], "intensity": 18, "range": 14,
             "path": [[-13, 7, 0], [13, 7, 0]], "period_frames": 300 },
  "camera": { "fov_y_degrees": 60,
              "path": [[-12, 1.8, 1.1], [0, 1.8, 1.1], [12, 1.8, 1.1]],
              "targets": [[-6, 1.2, -0.5], [4, 1.2, -0.5], [16, 1.5, -0.5]] }
}
""")
    write("scene_json", "minimal_obj", '{"meshes": [{"file": "m.obj"}]}')
    write("scene_json", "shared_and_deformed", """{"meshes": [
  { "file": "m.gltf", "transform": { "translate": [1, 0, 0] } },
  { "file": "m.gltf", "transform": { "translate": [2, 0, 0] } },
  { "file": "./m.gltf", "deform": { "type": "sine" } },
  { "file": "m.gltf", "deform": { "type": "sine" } }]}""")
    write("scene_json", "light_camera", """{"meshes": [{"file": "m.gltf"}], "frames": 100, "fps": 60,
  "light": {"color": [1, 0.5, 0.25], "intensity": 7, "range": 3, "path": [[0, 4, 0], [8, 4, 0]], "period_frames": 50},
  "camera": {"path": [[0, 1, 9], [1, 1, 9]], "fov_y_degrees": 40}, "sky_color": [0.1, 0.2, 0.3]}""")
    write("scene_json", "light_position_comments",
          '/* c */ {"meshes": [{"file": "m.obj"}], // line\n "light": {"position": [1, 2, 3]}}')
    write("scene_json", "assets_folder", '{"assets": ".", "meshes": [{"file": "m.obj"}, {"file": "m.gltf"}]}')
    write("scene_json", "unknown_key", '{"meshes": [{"file": "m.obj", "transfrom": {}}], "lights": {}}')
    write("scene_json", "bad_values", '{"meshes": [{"file": "m.obj", "transform": {"translate": [1, 1e300, 0],'
          ' "rotate": [1, 2]}, "material": {"reflectivity": 1.5}}], "frames": 2.5}')
    write("scene_json", "missing_file_floor", '{"meshes": [{"file": "m.gltf"}, {"file": "gone.glb"}],'
          ' "floor": {"materials": ["stone", "marble"], "reflectivity": 1}}')
    write("scene_json", "camera_one_point", '{"meshes": [{"file": "m.obj"}], "camera": {"path": [[0, 0, 0]],'
          ' "targets": [[0, 0, 0], [1, 1, 1]]}}')
    write("scene_json", "not_an_object", "[1, 2]")
    write("scene_json", "syntax_error", '{"meshes": [{"file": "m.obj"}, ]\n  "name": "x"')
    write("scene_json", "deform_errors", '{"meshes": [{"file": "m.obj", "deform": {"type": "twist", "axis": "w",'
          ' "ampltude": 1}}]}')


# --- textures (anything stb_image decodes; the tests use PNG, glTF adds JPEG) -------------------------
def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, bit_depth, colour_type, rows, extra=b""):
    raw = b"".join(b"\0" + row for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) + extra + png_chunk(b"IDAT", zlib.compress(raw))
            + png_chunk(b"IEND", b""))


def png_rgba(width, height, rgba):
    return png(width, height, 8, 6, [rgba[y * width * 4:(y + 1) * width * 4] for y in range(height)])


def bmp24(width, height):
    row = bytes([(x * 40) % 256 for x in range(width * 3)])
    row += b"\0" * (-len(row) % 4)
    pixels = row * height
    header = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    return b"BM" + struct.pack("<IHHI", 14 + len(header) + len(pixels), 0, 0, 14 + len(header)) + header + pixels


def tga_rle(width, height):
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, width, height, 24, 0x20)
    packet = bytes([0x80 | (width - 1), 10, 200, 30])  # one run per row
    return header + packet * height


def ffmpeg_image(name, codec_args, pixel_format, extension):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "out." + extension)
        subprocess.run(["ffmpeg", "-loglevel", "error", "-f", "lavfi", "-i", "testsrc=size=16x8:rate=1",
                        "-frames:v", "1", "-pix_fmt", pixel_format, *codec_args, path], check=True)
        with open(path, "rb") as f:
            write("texture", name, f.read())


def texture_seeds():
    gradient = bytes(v for y in range(4) for x in range(4) for v in (x * 60, y * 60, 128, 255 - x * 20))
    write("texture", "rgba8.png", png_rgba(4, 4, gradient))
    write("texture", "rgb8.png", png(3, 2, 8, 2, [bytes(range(9)), bytes(range(9, 18))]))
    write("texture", "gray8.png", png(4, 2, 8, 0, [bytes([0, 64, 128, 255])] * 2))
    write("texture", "gray_alpha16.png", png(2, 2, 16, 4, [bytes(range(8)), bytes(range(8, 16))]))
    write("texture", "palette4_trns.png",
          png(4, 2, 4, 3, [b"\x01\x23", b"\x32\x10"],
              png_chunk(b"PLTE", bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9])) + png_chunk(b"tRNS", b"\x80")))
    write("texture", "gray1.png", png(8, 2, 1, 0, [b"\xa5", b"\x5a"]))
    write("texture", "rgb24.bmp", bmp24(3, 2))
    write("texture", "rgb24_rle.tga", tga_rle(4, 2))
    write("texture", "binary.ppm", b"P6\n2 2\n255\n" + bytes(range(0, 240, 20)))
    ffmpeg_image("yuv420.jpg", ["-q:v", "5"], "yuvj420p", "jpg")
    ffmpeg_image("yuv444.jpg", ["-q:v", "5"], "yuvj444p", "jpg")
    ffmpeg_image("gray.jpg", ["-q:v", "5"], "gray", "jpg")
    ffmpeg_image("palette.gif", [], "pal8", "gif")


if __name__ == "__main__":
    obj_seeds()
    gltf_seeds()
    scene_json_seeds()
    texture_seeds()
    for target in sorted(os.listdir(ROOT)):
        files = os.listdir(os.path.join(ROOT, target))
        size = sum(os.path.getsize(os.path.join(ROOT, target, f)) for f in files)
        print(f"{target}: {len(files)} files, {size} bytes", file=sys.stderr)
