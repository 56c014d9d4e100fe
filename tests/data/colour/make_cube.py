#!/usr/bin/env python3
"""Writes the textured test cube in four forms (foldkit tests/test_face_colours.cpp):
cube.obj + cube.mtl (triangles), cube_quads.obj (the same cube as quads), cube.gltf + cube.bin and
cube.glb (embedded image), and glyphs.png: a 3x2 grid of coloured cells, each with an asymmetric glyph
(an "F") so that a mirrored or turned face shows. Five faces use the texture, the bottom face is flat red.
Run from this folder; the outputs are checked in."""
import json, struct, zlib

W = H = 192
CELL = (64, 96)
BACK = [(230, 180, 60), (70, 160, 220), (120, 200, 90), (220, 100, 160), (150, 110, 220), (240, 240, 240)]


def glyph(x, y):
    """An F in a 64x96 cell: vertical bar on the left, full top bar, half middle bar."""
    return (12 <= x < 24 and 12 <= y < 84) or (12 <= x < 52 and 12 <= y < 24) or (12 <= x < 40 and 42 <= y < 52)


def png(path):
    rows = []
    for y in range(H):  # y down in the image
        row = bytearray([0])
        for x in range(W):
            cell = (y // CELL[1]) * 3 + x // CELL[0]
            c = (20, 20, 20) if glyph(x % CELL[0], y % CELL[1]) else BACK[cell]
            row += bytes(c)
        rows.append(bytes(row))
    raw = zlib.compress(b"".join(rows), 9)

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)

    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) + \
        chunk(b"IDAT", raw) + chunk(b"IEND", b"")
    open(path, "wb").write(data)
    return data


# Unit cube faces, counter-clockwise from outside; corners listed from the cell's bottom-left (u, v up).
V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
FACES = [[4, 5, 6, 7], [1, 0, 3, 2], [5, 1, 2, 6], [0, 4, 7, 3], [7, 6, 2, 3], [0, 1, 5, 4]]
OFFSET = (2.0, -1.0, 0.5)  # the glTF node's translation, applied to the OBJ's coordinates


def cell_uv(k):
    """Texture coordinates (v up) of cell k's corners, inset by 4 texels."""
    cx, cy = k % 3, k // 3
    u0, u1 = (cx * 64 + 4) / W, (cx * 64 + 60) / W
    v_top, v_bottom = 1 - (cy * 96 + 4) / H, 1 - (cy * 96 + 92) / H
    return [(u0, v_bottom), (u1, v_bottom), (u1, v_top), (u0, v_top)]


def obj(path, quads):
    out = ["# foldkit test cube (tests/data/colour/make_cube.py)", "mtllib cube.mtl"]
    for p in V:
        out.append("v %g %g %g" % tuple(a + o for a, o in zip(p, OFFSET)))
    for k in range(6):
        for uv in cell_uv(k):
            out.append("vt %.6f %.6f" % uv)
    for k, f in enumerate(FACES):
        out.append("usemtl " + ("red" if k == 5 else "glyphs"))
        c = [(f[i] + 1, 4 * k + i + 1) for i in range(4)]
        tris = [c] if quads else [[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
        for t in tris:
            out.append("f " + " ".join("%d/%d" % x for x in t))
    open(path, "w").write("\n".join(out) + "\n")


def gltf(image):
    pos, uv, idx = [], [], []
    for k, f in enumerate(FACES):
        base = len(pos)
        for i, vi in enumerate(f):
            pos.append(V[vi])
            u, v = cell_uv(k)[i]
            uv.append((u, 1 - v))  # glTF: v down
    tri_idx = {0: [], 1: []}  # material 0 glyphs, 1 red
    for k in range(6):
        b = 4 * k
        tri_idx[1 if k == 5 else 0] += [b, b + 1, b + 2, b, b + 2, b + 3]
    bpos = b"".join(struct.pack("<3f", *p) for p in pos)
    buv = b"".join(struct.pack("<2f", *t) for t in uv)
    bi0 = b"".join(struct.pack("<H", i) for i in tri_idx[0])
    bi1 = b"".join(struct.pack("<H", i) for i in tri_idx[1])
    blob = bpos + buv + bi0 + bi1
    views = [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(bpos)},
        {"buffer": 0, "byteOffset": len(bpos), "byteLength": len(buv)},
        {"buffer": 0, "byteOffset": len(bpos) + len(buv), "byteLength": len(bi0)},
        {"buffer": 0, "byteOffset": len(bpos) + len(buv) + len(bi0), "byteLength": len(bi1)},
    ]
    acc = [
        {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
        {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC2"},
        {"bufferView": 2, "componentType": 5123, "count": len(tri_idx[0]), "type": "SCALAR"},
        {"bufferView": 3, "componentType": 5123, "count": len(tri_idx[1]), "type": "SCALAR"},
    ]
    doc = {
        "asset": {"version": "2.0", "generator": "foldkit make_cube.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": list(OFFSET)}],
        "meshes": [{"primitives": [
            {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0},
            {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 3, "material": 1}]}],
        "materials": [
            {"name": "glyphs", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 1]}},
            {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1]}}],
        "textures": [{"source": 0}],
        "accessors": acc, "bufferViews": views,
    }
    # .gltf: buffer and image beside it.
    open("cube.bin", "wb").write(blob)
    d = json.loads(json.dumps(doc))
    d["buffers"] = [{"uri": "cube.bin", "byteLength": len(blob)}]
    d["images"] = [{"uri": "glyphs.png"}]
    open("cube.gltf", "w").write(json.dumps(d, indent=1) + "\n")
    # .glb: the image in the binary chunk.
    pad = (4 - len(blob) % 4) % 4
    blob2 = blob + b"\0" * pad
    d = json.loads(json.dumps(doc))
    d["bufferViews"].append({"buffer": 0, "byteOffset": len(blob2), "byteLength": len(image)})
    blob2 += image + b"\0" * ((4 - len(image) % 4) % 4)
    d["buffers"] = [{"byteLength": len(blob2)}]
    d["images"] = [{"bufferView": 4, "mimeType": "image/png"}]
    js = json.dumps(d).encode()
    js += b" " * ((4 - len(js) % 4) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(blob2), 0x004E4942) + blob2
    open("cube.glb", "wb").write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


image = png("glyphs.png")
open("cube.mtl", "w").write("newmtl glyphs\nKd 1 1 1\nmap_Kd glyphs.png\n\nnewmtl red\nKd 0.8 0.1 0.1\n")
obj("cube.obj", quads=False)
obj("cube_quads.obj", quads=True)
gltf(image)
