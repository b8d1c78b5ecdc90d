#!/usr/bin/env python3
"""Write an OBJ model's mesh as PLY, STL, glTF or GLB, for tests and for trying formats.

    python3 tools/convert_model.py IN.obj OUT.ply [--ascii] [--big-endian]
    python3 tools/convert_model.py IN.obj OUT.stl [--ascii]
    python3 tools/convert_model.py IN.obj OUT.gltf|OUT.glb [--base-color R,G,B]
                                   [--metallic M] [--roughness R] [--texture IMAGE.png]

Reads the OBJ's `v x y z [r g b]` and `f` lines (any corner form: the position index is
used; 1-based or negative), nothing else. Writes the same positions, as single-precision
floats (the formats' own), and the same faces:

- PLY keeps each face whole (a quad stays a quad) and the vertex colours (as uchar);
  binary little-endian unless --ascii or --big-endian.
- STL has triangles only, each face split as a fan from its first corner, and no shared
  vertices; facet normals are written as the triangles' own; binary unless --ascii.
- glTF 2.0 (a .gltf with its buffer beside it as OUT.bin, or one .glb) has one mesh of
  fan-split triangles, indexed, with COLOR_0 when the OBJ has colours, and one material:
  --base-color (default 1,1,1), --metallic (default 0) and --roughness (default 1).
  With --texture, the material's base colour texture is that PNG (beside a .gltf, named by
  its file name, which is copied there when it is elsewhere; inside a .glb) and the mesh has
  TEXCOORD_0 from the OBJ's `vt` (v turned down, as glTF has it), each vertex a position
  with its texture coordinates.

Deterministic, standard library only; prints nothing but errors (exit 1).
"""

import argparse
import json
import math
import os
import struct
import sys


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def read_obj(path):
    """(positions [(x, y, z)], colours [(r, g, b)] or None, faces [[index]], texcoords
    [(u, v)], each face's corners' texcoord indices [[index or None]])."""
    positions, colours, faces, texcoords, face_texcoords = [], [], [], [], []
    with open(path) as handle:
        for number, line in enumerate(handle, 1):
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                values = [float(w) for w in words[1:]]
                positions.append(tuple(f32(v) for v in values[:3]))
                colours.append(tuple(values[3:6]) if len(values) >= 6 else None)
            elif words[0] == "vt":
                values = [float(w) for w in words[1:3]]
                texcoords.append((values[0], values[1] if len(values) > 1 else 0.0))
            elif words[0] == "f":
                face, corners = [], []
                for corner in words[1:]:
                    parts = corner.split("/")
                    index = int(parts[0])
                    face.append(index - 1 if index > 0 else len(positions) + index)
                    t = int(parts[1]) if len(parts) > 1 and parts[1] else None
                    corners.append(None if t is None else t - 1 if t > 0 else len(texcoords) + t)
                face_texcoords.append(corners)
                if len(face) < 3 or not all(0 <= i < len(positions) for i in face):
                    sys.exit("%s:%d: error: a face needs 3 or more corners that name vertices" % (path, number))
                faces.append(face)
    if not faces:
        sys.exit("%s: error: no faces (f) found" % path)
    has_colours = any(c is not None for c in colours)
    return (positions, ([c or (1.0, 1.0, 1.0) for c in colours] if has_colours else None), faces, texcoords,
            face_texcoords)


def with_texcoords(positions, colours, faces, texcoords, face_texcoords):
    """The mesh with a vertex per distinct (position, texcoords) of its corners, as glTF
    has them: (positions, colours, faces, the vertices' texcoords)."""
    vertex_of, new_positions, new_colours, new_texcoords, new_faces = {}, [], [], [], []
    for face, corners in zip(faces, face_texcoords):
        new_face = []
        for p, t in zip(face, corners):
            key = (p, t)
            if key not in vertex_of:
                vertex_of[key] = len(new_positions)
                new_positions.append(positions[p])
                new_colours.append(colours[p] if colours else None)
                new_texcoords.append(texcoords[t] if t is not None else (0.0, 0.0))
            new_face.append(vertex_of[key])
        new_faces.append(new_face)
    return new_positions, (new_colours if colours else None), new_faces, new_texcoords


def fan(face):
    return [(face[0], face[i], face[i + 1]) for i in range(1, len(face) - 1)]


def byte(c):
    return max(0, min(255, int(round(c * 255.0))))


def write_ply(path, positions, colours, faces, ascii_text, big_endian):
    kind = "ascii" if ascii_text else ("binary_big_endian" if big_endian else "binary_little_endian")
    header = ["ply", "format %s 1.0" % kind, "comment written by tools/convert_model.py",
              "element vertex %d" % len(positions), "property float x", "property float y", "property float z"]
    if colours:
        header += ["property uchar red", "property uchar green", "property uchar blue"]
    header += ["element face %d" % len(faces), "property list uchar int vertex_indices", "end_header"]
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode())
        order = ">" if big_endian else "<"
        for i, p in enumerate(positions):
            if ascii_text:
                text = "%r %r %r" % p
                if colours:
                    text += " %d %d %d" % tuple(byte(c) for c in colours[i])
                out.write((text + "\n").encode())
            else:
                out.write(struct.pack(order + "3f", *p))
                if colours:
                    out.write(struct.pack("3B", *(byte(c) for c in colours[i])))
        for face in faces:
            if ascii_text:
                out.write(("%d %s\n" % (len(face), " ".join(str(i) for i in face))).encode())
            else:
                out.write(struct.pack(order + "B%di" % len(face), len(face), *face))


def normal_of(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / length for x in n]


def write_stl(path, positions, faces, ascii_text):
    triangles = [t for face in faces for t in fan(face)]
    with open(path, "wb") as out:
        if ascii_text:
            out.write(b"solid model\n")
            for t in triangles:
                corners = [positions[i] for i in t]
                out.write(("  facet normal %r %r %r\n    outer loop\n" % tuple(normal_of(*corners))).encode())
                for p in corners:
                    out.write(("      vertex %r %r %r\n" % p).encode())
                out.write(b"    endloop\n  endfacet\n")
            out.write(b"endsolid model\n")
        else:
            out.write(b"binary STL written by tools/convert_model.py".ljust(80, b" "))
            out.write(struct.pack("<I", len(triangles)))
            for t in triangles:
                corners = [positions[i] for i in t]
                out.write(struct.pack("<3f", *normal_of(*corners)))
                for p in corners:
                    out.write(struct.pack("<3f", *p))
                out.write(b"\0\0")


def gltf_parts(positions, colours, faces, material, texcoords=None, image=None):
    """(the glTF JSON as a dict, its binary buffer). With texcoords, TEXCOORD_0 and a base
    colour texture: image is the PNG's bytes to hold in the buffer, or None for one named by
    material["texture"]."""
    indices = [i for face in faces for t in fan(face) for i in t]
    blob = bytearray()
    blob += struct.pack("<%dI" % len(indices), *indices)
    index_bytes = len(blob)
    position_offset = len(blob)
    for p in positions:
        blob += struct.pack("<3f", *p)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": index_bytes, "target": 34963},
             {"buffer": 0, "byteOffset": position_offset, "byteLength": 12 * len(positions), "target": 34962}]
    low = [min(p[k] for p in positions) for k in range(3)]
    high = [max(p[k] for p in positions) for k in range(3)]
    accessors = [{"bufferView": 0, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
                 {"bufferView": 1, "componentType": 5126, "count": len(positions), "type": "VEC3",
                  "min": low, "max": high}]
    attributes = {"POSITION": 1}
    if colours:
        colour_offset = len(blob)
        for c in colours:
            blob += struct.pack("<3f", *c)
        views.append({"buffer": 0, "byteOffset": colour_offset, "byteLength": 12 * len(colours), "target": 34962})
        accessors.append({"bufferView": 2, "componentType": 5126, "count": len(colours), "type": "VEC3"})
        attributes["COLOR_0"] = 2
    if texcoords is not None:
        texcoord_offset = len(blob)
        for u, v in texcoords:
            blob += struct.pack("<2f", u, 1.0 - v)  # glTF's v runs down the image
        views.append({"buffer": 0, "byteOffset": texcoord_offset, "byteLength": 8 * len(texcoords),
                      "target": 34962})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": len(texcoords),
                          "type": "VEC2"})
        attributes["TEXCOORD_0"] = len(accessors) - 1
    image_entry = None
    if texcoords is not None and image is not None:
        image_offset = len(blob)
        blob += image
        views.append({"buffer": 0, "byteOffset": image_offset, "byteLength": len(image)})
        image_entry = {"bufferView": len(views) - 1, "mimeType": "image/png"}
    elif texcoords is not None:
        image_entry = {"uri": os.path.basename(material["texture"])}
    while len(blob) % 4:
        blob += b"\0"
    document = {
        "asset": {"version": "2.0", "generator": "tools/convert_model.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": 0, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {
            "baseColorFactor": list(material["base"]) + [1.0],
            "metallicFactor": material["metallic"], "roughnessFactor": material["roughness"]}}],
        "buffers": [{"byteLength": len(blob)}], "bufferViews": views, "accessors": accessors}
    if image_entry is not None:
        document["images"] = [image_entry]
        document["textures"] = [{"source": 0}]
        document["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return document, bytes(blob)


def write_gltf(path, positions, colours, faces, material, texcoords=None):
    document, blob = gltf_parts(positions, colours, faces, material, texcoords)
    if texcoords is not None:
        beside = os.path.join(os.path.dirname(path), os.path.basename(material["texture"]))
        if os.path.abspath(beside) != os.path.abspath(material["texture"]):
            with open(material["texture"], "rb") as source, open(beside, "wb") as out:
                out.write(source.read())
    binary = os.path.splitext(path)[0] + ".bin"
    document["buffers"][0]["uri"] = os.path.basename(binary)
    with open(binary, "wb") as out:
        out.write(blob)
    with open(path, "w") as out:
        json.dump(document, out, indent=1)
        out.write("\n")


def write_glb(path, positions, colours, faces, material, texcoords=None):
    image = None
    if texcoords is not None:
        with open(material["texture"], "rb") as source:
            image = source.read()
    document, blob = gltf_parts(positions, colours, faces, material, texcoords, image)
    text = json.dumps(document).encode()
    while len(text) % 4:
        text += b" "
    total = 12 + 8 + len(text) + 8 + len(blob)
    with open(path, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, total))
        out.write(struct.pack("<I4s", len(text), b"JSON") + text)
        out.write(struct.pack("<I4s", len(blob), b"BIN\0") + blob)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--ascii", action="store_true", help="PLY or STL as text")
    parser.add_argument("--big-endian", action="store_true", help="binary PLY, big-endian")
    parser.add_argument("--base-color", default="1,1,1", help="glTF base colour R,G,B")
    parser.add_argument("--metallic", type=float, default=0.0)
    parser.add_argument("--roughness", type=float, default=1.0)
    parser.add_argument("--texture", help="glTF base colour texture: a PNG file")
    args = parser.parse_args()
    positions, colours, faces, texcoords, face_texcoords = read_obj(args.input)
    extension = os.path.splitext(args.output)[1].lower()
    material = {"base": [float(v) for v in args.base_color.split(",")], "metallic": args.metallic,
                "roughness": args.roughness, "texture": args.texture}
    uvs = None
    if args.texture and extension in (".gltf", ".glb"):
        positions, colours, faces, uvs = with_texcoords(positions, colours, faces, texcoords, face_texcoords)
    if extension == ".ply":
        write_ply(args.output, positions, colours, faces, args.ascii, args.big_endian)
    elif extension == ".stl":
        write_stl(args.output, positions, faces, args.ascii)
    elif extension == ".gltf":
        write_gltf(args.output, positions, colours, faces, material, uvs)
    elif extension == ".glb":
        write_glb(args.output, positions, colours, faces, material, uvs)
    else:
        sys.exit("%s: error: the output must end in .ply, .stl, .gltf or .glb" % args.output)


if __name__ == "__main__":
    main()
