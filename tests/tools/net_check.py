#!/usr/bin/env python3
"""Independent check of a flat net written by `foldkit unfold MESH -o NET.obj`, against the model file.

usage: net_check.py MODEL.(obj|off|ply) NET.obj [--mm-per-unit S --room WxH] [--flat-angle DEG] [--json]

It shares no code with foldkit: it reads both files itself, uses shapely for the geometry, and holds the
net to what issue 11 promises of the parts:
- face k of the net is polygon k of the model, with as many corners, congruent (every distance between
  two corners the same, within a ten-millionth of the model's size, plus what reading the coordinates
  as single-precision floats moves them where that is less than a millionth of its size: foldkit reads
  them so there, and as written elsewhere), in the same turning order and counter-clockwise: nothing
  mirrored;
- every polygon of the model that is planar within --flat-angle (default 0.5 degrees) is one polygon of
  the net: a flat face is never cut;
- the corners a fold joins are corners of one model vertex, and two faces meet along a net edge only
  where they meet along that edge on the model: every fold is a real edge, every cut has its partner;
- no corner is shared between two pieces (the OBJ's `g` groups), and each piece is connected;
- no two faces of one piece overlap (more than a trillionth of the piece's area);
- with --mm-per-unit and --room, every piece fits a W x H mm rectangle at some rotation (every tenth
  of a degree, and every hull edge laid along a side).
Exit 0 when all holds; 1 with one line per problem; 2 on a file it cannot read; 77 when shapely is
missing (Debian: python3-shapely), so that a test can skip.
"""
import argparse
import json
import math
import numbers
import struct
import sys
import warnings
from collections import defaultdict, deque

try:
    from shapely.geometry import MultiPoint, Polygon
    from shapely.strtree import STRtree
except ImportError:
    print("shapely is not installed (Debian: python3-shapely)")
    sys.exit(77)

RELATIVE_TOLERANCE = 1e-7  # of the model's largest dimension: lengths after long chains of folds
# foldkit reads an OBJ's or PLY's coordinates as single-precision floats (as OpenMesh and Blender do) unless that
# moves some point by more than this share of the model's size; then it takes them as written.
FLOAT_SHIFT_SHARE = 1e-6
OVERLAP_SHARE = 1e-12  # of a piece's area: touching along an edge is no overlap, a crossing is
FIT_SLACK_MM = 1e-6


class Unreadable(Exception):
    pass


def read_model(path):
    """Vertices (deduplicated by position: one model vertex per point) and polygons as vertex lists."""
    if path.lower().endswith(".ply"):
        with open(path, "rb") as f:
            return read_ply(f.read())
    text = open(path, encoding="utf-8", errors="replace").read()
    if path.lower().endswith(".off"):
        return read_off(text)
    points, faces = [], []
    for line in text.splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            points.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "f":
            face = []
            for token in parts[1:]:
                i = int(token.split("/")[0])
                face.append(i - 1 if i > 0 else len(points) + i)
            faces.append(face)
    return weld(points, faces)


def read_off(text):
    words = [w for line in text.splitlines() for w in line.split("#")[0].split()]
    if not words or not words[0].endswith("OFF"):
        raise Unreadable("not an OFF file")
    at = 1
    nv, nf = int(words[at]), int(words[at + 1])
    at += 3
    points = []
    for _ in range(nv):
        points.append(tuple(float(x) for x in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(x) for x in words[at + 1:at + 1 + n]])
        at += 1 + n
    return weld(points, faces)

PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
             "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


def read_ply(data):
    """A PLY of vertices (x, y, z among scalar properties) and faces (one index list), ASCII or binary."""
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise Unreadable("not a PLY file")
    body = data[data.index(b"\n", end) + 1:]
    fmt, elements = None, []
    for line in data[:end].decode("ascii", "replace").splitlines()[1:]:
        w = line.split()
        if not w or w[0] in ("comment", "obj_info"):
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append(tuple(w[1:]))
    if fmt == "ascii":
        return ply_from_values(elements, iter(body.decode("ascii").split()), None)
    order = "<" if fmt == "binary_little_endian" else ">"
    return ply_from_values(elements, body, order)


def ply_from_values(elements, source, order):
    """Reads each element's records from an iterator of ASCII words (order None) or from bytes."""
    at = 0

    def take(kind):
        nonlocal at
        if order is None:
            word = next(source)
            return float(word) if PLY_TYPES[kind] in "fd" else int(word)
        size = struct.calcsize(PLY_TYPES[kind])
        (value,) = struct.unpack_from(order + PLY_TYPES[kind], source, at)
        at += size
        return value

    points, faces = [], []
    for name, count, props in elements:
        for _ in range(count):
            record = {}
            for prop in props:
                if prop[0] == "list":
                    record[prop[3]] = [take(prop[2]) for _ in range(take(prop[1]))]
                else:
                    record[prop[1]] = take(prop[0])
            if name == "vertex":
                points.append((float(record["x"]), float(record["y"]), float(record["z"])))
            elif name == "face":
                faces.append(record.get("vertex_indices", record.get("vertex_index")))
    return weld(points, faces)


def weld(points, faces):
    index, welded, remap = {}, [], []
    for p in points:
        if p not in index:
            index[p] = len(welded)
            welded.append(p)
        remap.append(index[p])
    return welded, [[remap[i] for i in f] for f in faces]


def read_net(path):
    points, faces, groups, header = [], [], [], []
    group = None
    for line in open(path, encoding="utf-8"):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "#":
            header.append(line.strip())
        elif parts[0] == "v":
            x, y, z = (float(v) for v in parts[1:4])
            if z != 0:
                raise Unreadable(f"net vertex {len(points) + 1} is not flat (z = {z})")
            points.append((x, y))
        elif parts[0] == "g":
            group = parts[1]
        elif parts[0] == "f":
            faces.append([int(t.split("/")[0]) - 1 for t in parts[1:]])
            groups.append(group)
    return points, faces, groups, header


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dist(a, b):
    return math.sqrt(sum(d * d for d in sub(a, b)))


def cross3(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def newell_normal(corners):
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(corners):
        q = corners[(i + 1) % len(corners)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return n


def angle_between(a, b):
    na, nb = math.sqrt(sum(x * x for x in a)), math.sqrt(sum(x * x for x in b))
    if na == 0 or nb == 0:
        return 0.0
    c = sum(x * y for x, y in zip(a, b)) / (na * nb)
    return math.acos(max(-1.0, min(1.0, c)))


def planar(corners, flat_angle_rad):
    """Whether every corner's turn lies within the flat angle of the polygon's mean plane."""
    if len(corners) <= 3:
        return True
    n = newell_normal(corners)
    for i in range(len(corners)):
        a, b, c = corners[i - 1], corners[i], corners[(i + 1) % len(corners)]
        local = cross3(sub(b, a), sub(c, b))
        if math.sqrt(sum(x * x for x in local)) == 0:
            continue
        turn = angle_between(local, n)
        # A reflex corner of a planar non-convex polygon turns the other way: its normal is opposite.
        if min(turn, math.pi - turn) > flat_angle_rad:
            return False
    return True


def single(x):
    """x as a single-precision float holds it."""
    return struct.unpack("f", struct.pack("f", x))[0]


def signed_area(poly):
    return 0.5 * sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
                     for i in range(len(poly)))


class Check:
    def __init__(self, model_points, model_faces, net_points, net_faces, groups, header):
        self.mp, self.mf = model_points, model_faces
        self.np, self.nf, self.groups, self.header = net_points, net_faces, groups, header
        lo = [min(p[k] for p in model_points) for k in range(3)]
        hi = [max(p[k] for p in model_points) for k in range(3)]
        self.extent = max(h - l for h, l in zip(hi, lo))
        shift = max(abs(x - single(x)) for p in model_points for x in p)
        # Single precision where foldkit keeps it: two corners each moved by `shift` along each axis.
        allowed = 2 * math.sqrt(3) * shift if shift <= FLOAT_SHIFT_SHARE * self.extent else 0
        self.tol = RELATIVE_TOLERANCE * self.extent + allowed
        self.problems = []
        self.turn = [None] * len(net_faces)  # per face: which model corner its net corner 0 is

    def problem(self, text):
        self.problems.append(text)

    def rotations(self, k):
        """The turns r that make net corner i of face k model corner (i + r) of polygon k."""
        net = [self.np[v] for v in self.nf[k]]
        model = [self.mp[v] for v in self.mf[k]]
        n = len(net)
        found = []
        for r in range(n):
            if all(abs(dist(net[i], net[j]) - dist(model[(i + r) % n], model[(j + r) % n])) <= self.tol
                   for i in range(n) for j in range(i + 1, n)):
                found.append(r)
        return found

    def faces(self, flat_angle_rad):
        if len(self.nf) != len(self.mf):
            self.problem(f"the net has {len(self.nf)} faces, the model {len(self.mf)} polygons")
            return False
        for k, (net, model) in enumerate(zip(self.nf, self.mf)):
            if len(net) != len(model):
                whole = "cut" if planar([self.mp[v] for v in model], flat_angle_rad) else "folded"
                self.problem(f"face {k + 1}: {len(net)} corners in the net, {len(model)} on the model "
                             f"(a {'flat' if whole == 'cut' else 'non-planar'} polygon written in pieces)")
                continue
            if signed_area([self.np[v] for v in net]) <= 0:
                self.problem(f"face {k + 1} is mirrored or degenerate in the net")
            turns = self.rotations(k)
            if not turns:
                self.problem(f"face {k + 1} is not congruent to polygon {k + 1} of the model")
            self.turn[k] = turns
        return not self.problems

    def model_vertex(self, k, r, v):
        """The model vertex of net vertex v as a corner of face k turned by r."""
        n = len(self.nf[k])
        return self.mf[k][(self.nf[k].index(v) + r) % n]

    def corner_vertices(self):
        """Each net vertex's model vertex. A symmetric face (a square, a regular pentagon) is congruent at
        several turns: the folds decide, as constraints between the two faces of each shared net edge
        (arc consistency, then faces assigned breadth-first along folds). A net vertex left with two
        model vertices is a fold between wrong corners."""
        shared = defaultdict(list)  # net edge as walked -> faces
        for k, f in enumerate(self.nf):
            for i in range(len(f)):
                shared[(f[i], f[(i + 1) % len(f)])].append(k)
        neighbours = defaultdict(list)  # face -> (other face, net edge)
        for (a, b), ks in shared.items():
            for k in ks:
                for l in shared.get((b, a), []):
                    neighbours[k].append((l, (a, b)))

        def agree(k, r, l, s, edge):
            return all(self.model_vertex(k, r, v) == self.model_vertex(l, s, v) for v in edge)

        domain = [list(t) for t in self.turn]
        queue = deque((k, l, e) for k in neighbours for l, e in neighbours[k])
        while queue:
            k, l, e = queue.popleft()
            kept = [r for r in domain[k] if any(agree(k, r, l, s, e) for s in domain[l])]
            if len(kept) < len(domain[k]):
                domain[k] = kept
                queue.extend((m, k, f) for m, f in neighbours[k] if m != l)
        of, chosen = {}, [None] * len(self.nf)
        for start in range(len(self.nf)):
            if chosen[start] is not None:
                continue
            todo = deque([start])
            while todo:
                k = todo.popleft()
                if chosen[k] is not None:
                    continue
                fits = [r for r in domain[k]
                        if all(chosen[l] is None or agree(k, r, l, chosen[l], e) for l, e in neighbours[k])]
                if not fits:
                    self.problem(f"face {k + 1} meets its folded neighbours at corners of other model vertices")
                    fits = self.turn[k]
                chosen[k] = fits[0]
                for v in self.nf[k]:
                    m = self.model_vertex(k, chosen[k], v)
                    if of.setdefault(v, m) != m:
                        self.problem(f"net vertex {v + 1} joins corners of model vertices {of[v] + 1} and {m + 1}")
                todo.extend(l for l, _ in neighbours[k] if chosen[l] is None)
        return of

    def folds_and_seams(self, of):
        model_edges = defaultdict(list)  # model edge (a, b) as walked by a face -> faces
        for k, f in enumerate(self.mf):
            for i in range(len(f)):
                model_edges[(f[i], f[(i + 1) % len(f)])].append(k)
        net_edges = defaultdict(list)
        for k, f in enumerate(self.nf):
            for i in range(len(f)):
                net_edges[(f[i], f[(i + 1) % len(f)])].append(k)
        folds = set()
        for (a, b), ks in net_edges.items():
            for k in ks:
                for l in net_edges.get((b, a), []):
                    if k >= l:
                        continue
                    ma, mb = of[a], of[b]
                    if k not in model_edges.get((ma, mb), []) or l not in model_edges.get((mb, ma), []):
                        self.problem(f"faces {k + 1} and {l + 1} are folded along a net edge that is no "
                                     f"edge between them on the model")
                    folds.add((min(k, l), max(k, l)))
        seams = between_pieces = 0
        for (a, b), ks in model_edges.items():
            for k in ks:
                for l in model_edges.get((b, a), []):
                    if k < l and (k, l) not in folds:
                        seams += 1
                        between_pieces += self.groups[k] != self.groups[l]
        return folds, seams, between_pieces

    def pieces(self, folds):
        group_of_vertex = {}
        for k, f in enumerate(self.nf):
            for v in f:
                if group_of_vertex.setdefault(v, self.groups[k]) != self.groups[k]:
                    self.problem(f"net vertex {v + 1} is shared by {group_of_vertex[v]} and {self.groups[k]}")
        members = defaultdict(list)
        for k, g in enumerate(self.groups):
            members[g].append(k)
        links = defaultdict(list)
        for k, l in folds:
            links[k].append(l)
            links[l].append(k)
        for g, faces in members.items():
            seen, queue = {faces[0]}, deque([faces[0]])
            while queue:
                for l in links[queue.popleft()]:
                    if l not in seen:
                        seen.add(l)
                        queue.append(l)
            if len(seen) != len(faces):
                self.problem(f"{g} falls apart: {len(seen)} of its {len(faces)} faces hang together by folds")
        return members

    def overlaps(self, members):
        worst = 0.0
        for g, faces in members.items():
            polys = [Polygon([self.np[v] for v in self.nf[k]]) for k in faces]
            for k, p in zip(faces, polys):
                if not p.is_valid:
                    self.problem(f"face {k + 1} crosses itself in the net")
            area = sum(p.area for p in polys)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # shapely 1.8 warns of 2.0's STRtree; both are handled
                tree = STRtree(polys)
            index = {id(p): i for i, p in enumerate(polys)}
            for i, p in enumerate(polys):
                for q in tree.query(p):
                    j = int(q) if isinstance(q, (int, numbers.Integral)) else index[id(q)]
                    if j <= i:
                        continue
                    shared = p.intersection(q).area
                    worst = max(worst, shared / area)
                    if shared > OVERLAP_SHARE * area:
                        self.problem(f"{g}: faces {faces[i] + 1} and {faces[j] + 1} overlap "
                                     f"({shared / area:.2e} of the piece)")
        return worst

    def fits(self, members, mm_per_unit, room):
        tightest = 0.0  # the largest share of the room a piece needs, at its best rotation
        for g, faces in members.items():
            points = [self.np[v] for k in faces for v in self.nf[k]]
            hull = MultiPoint(points).convex_hull
            coords = list(hull.exterior.coords)[:-1] if hull.geom_type == "Polygon" else list(hull.coords)
            coords = [(x * mm_per_unit, y * mm_per_unit) for x, y in coords]
            angles = [math.radians(t / 10) for t in range(1800)]
            for i in range(len(coords)):
                dx, dy = sub(coords[(i + 1) % len(coords)], coords[i])
                angles += [-math.atan2(dy, dx), -math.atan2(dy, dx) + math.pi / 2]
            need = math.inf
            for a in angles:
                c, s = math.cos(a), math.sin(a)
                xs = [c * x - s * y for x, y in coords]
                ys = [s * x + c * y for x, y in coords]
                w, h = max(xs) - min(xs), max(ys) - min(ys)
                need = min(need, max(w / room[0], h / room[1]))
            tightest = max(tightest, need)
            if need > 1 + FIT_SLACK_MM / min(room):
                self.problem(f"{g} does not fit the {room[0]:g} x {room[1]:g} mm room at any rotation "
                             f"(it needs {need:.3f} of it)")
        return tightest


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("model")
    ap.add_argument("net")
    ap.add_argument("--mm-per-unit", type=float)
    ap.add_argument("--room", help="W x H in mm, e.g. 174x261")
    ap.add_argument("--flat-angle", type=float, default=0.5, help="degrees")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    try:
        model_points, model_faces = read_model(a.model)
        net_points, net_faces, groups, header = read_net(a.net)
    except (OSError, ValueError, IndexError, KeyError, StopIteration, struct.error, Unreadable) as e:
        print(f"{a.net}: cannot read: {e}")
        return 2
    c = Check(model_points, model_faces, net_points, net_faces, groups, header)
    summary = {"faces": len(net_faces), "pieces": len(set(groups))}
    if c.faces(math.radians(a.flat_angle)):
        of = c.corner_vertices()
        folds, seams, between = c.folds_and_seams(of)
        members = c.pieces(folds)
        summary.update(folds=len(folds), seams=seams, seams_between_pieces=between,
                       worst_overlap_share=c.overlaps(members))
        if a.mm_per_unit and a.room:
            room = tuple(float(x) for x in a.room.lower().split("x"))
            summary["tightest_room_share"] = c.fits(members, a.mm_per_unit, room)
    summary["problems"] = c.problems
    if a.json:
        print(json.dumps(summary))
    else:
        for p in c.problems:
            print(f"{a.net}: {p}")
        if not c.problems:
            print(f"{a.net}: ok: " + ", ".join(f"{k} {v:.3g}" if isinstance(v, float) else f"{k} {v}"
                                                for k, v in summary.items() if k != "problems"))
    return 1 if c.problems else 0


if __name__ == "__main__":
    sys.exit(main())
