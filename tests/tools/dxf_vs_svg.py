#!/usr/bin/env python3
"""Independent check of foldkit's DXF: reads it back with ezdxf and compares it with the SVG of the
same sheet.  usage: dxf_vs_svg.py SHEET.svg SHEET.dxf

Every path of the SVG groups cut, mountain, valley, tab and regmark must be a polyline on the DXF layer
of the same name in capitals, at the same place (DXF point = (x, -y) of the SVG point) within 0.01 mm,
and vice versa; texts must appear as strokes on the LABEL layer (POLYLINEs: no TEXT, MTEXT or INSERT,
which a program without the font would not show), and where the SVG has no text elements (the
bundle's cut-line SVG) its label group must match the LABEL layer path for path; $INSUNITS must say millimetres; $EXTMIN and
$EXTMAX must span the SVG's page with the origin at its top-left corner, (0, -height) to (width, 0).
Exit 0 when all holds, 1 with one line per difference, 77 when ezdxf is missing (the test then skips).
"""
import re
import sys
import xml.etree.ElementTree as ET

try:
    import ezdxf
except ImportError:
    print("ezdxf is not installed (Debian: python3-ezdxf)")
    sys.exit(77)

TOLERANCE_MM = 0.01
ROLES = ["cut", "mountain", "valley", "tab", "regmark"]
SVG = "{http://www.w3.org/2000/svg}"


def svg_paths(path):
    root = ET.parse(path).getroot()
    width, height = (float(root.get(k).removesuffix("mm")) for k in ("width", "height"))
    out = {}
    texts = len(list(root.iter(SVG + "text")))
    for g in root.iter(SVG + "g"):
        role = g.get("id")
        if role is None:
            continue
        for p in g.findall(SVG + "path"):
            d = p.get("d")
            nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]
            pts = list(zip(nums[0::2], nums[1::2]))
            out.setdefault(role, []).append((pts, d.rstrip().endswith("Z")))
    return (width, height), out, texts


def dxf_paths(path):
    doc = ezdxf.readfile(path)
    out, others = {}, {}
    for e in doc.modelspace():
        if e.dxftype() not in ("POLYLINE", "LWPOLYLINE"):
            others[e.dxftype()] = others.get(e.dxftype(), 0) + 1
        if e.dxftype() == "POLYLINE":
            pts = [(v.dxf.location.x, v.dxf.location.y) for v in e.vertices]
            closed = e.is_closed
        elif e.dxftype() == "LWPOLYLINE":
            pts = [(x, y) for x, y, *_ in e.get_points()]
            closed = e.closed
        else:
            continue
        out.setdefault(e.dxf.layer, []).append((pts, closed))
    return doc, out, others


def key(pts):
    return tuple(round(c, 1) for p in pts[:2] for c in p)


def deviation(a, b):
    return max(max(abs(p[0] - q[0]), abs(p[1] - q[1])) for p, q in zip(a, b))


def same(a, b):
    return len(a) == len(b) and deviation(a, b) <= TOLERANCE_MM


def main():
    svg_file, dxf_file = sys.argv[1], sys.argv[2]
    size, svg, texts = svg_paths(svg_file)
    doc, dxf, others = dxf_paths(dxf_file)
    problems = []
    if doc.header.get("$INSUNITS") != 4:
        problems.append(f"$INSUNITS is {doc.header.get('$INSUNITS')}, not 4 (mm)")
    for kind, count in sorted(others.items()):
        problems.append(f"{count} {kind} entities: every line and label must be a polyline")
    w, h = size
    for var, want in (("$EXTMIN", (0.0, -h)), ("$EXTMAX", (w, 0.0))):
        have = doc.header.get(var)
        if have is None or abs(have[0] - want[0]) > TOLERANCE_MM or abs(have[1] - want[1]) > TOLERANCE_MM:
            problems.append(f"{var} is {have}, not {want}: the page with its origin at the top-left")
    named = ["CUT", "MOUNTAIN", "VALLEY", "TAB", "LABEL", "REGMARK"]
    layers = {layer.dxf.name for layer in doc.layers}
    for name in named:
        if name not in layers:
            problems.append(f"layer {name} is not declared")
    for layer in dxf:
        if layer not in named:
            problems.append(f"polylines on layer {layer}, which is none of {' '.join(named)}")
    compared, worst = 0, 0.0
    # An SVG without text elements (the bundle's cut-line SVG) draws the labels as the DXF's strokes:
    # compared too. A print SVG writes texts, which only the stroke count below can check.
    for role in ROLES + ([] if texts else ["label"]):
        want = [([(x, -y) for x, y in pts], closed) for pts, closed in svg.get(role, [])]
        have = list(dxf.get(role.upper(), []))
        if len(want) != len(have):
            problems.append(f"{role}: {len(want)} paths in the SVG, {len(have)} on layer {role.upper()}")
            continue
        pool = {}
        for i, (pts, closed) in enumerate(have):
            pool.setdefault(key(pts), []).append(i)
        used = set()
        for pts, closed in want:
            match = None
            for i in pool.get(key(pts), []) + list(range(len(have))):
                if i not in used and have[i][1] == closed and same(pts, have[i][0]):
                    match = i
                    break
            if match is None:
                problems.append(f"{role}: path starting at {pts[0]} has no DXF polyline within {TOLERANCE_MM} mm")
                continue
            used.add(match)
            compared += 1
            worst = max(worst, deviation(pts, have[match][0]))
    strokes = dxf.get("LABEL", [])
    if texts and not strokes:
        problems.append(f"{texts} label texts in the SVG, no strokes on layer LABEL")
    for layer, lines in dxf.items():
        for pts, _ in lines:
            for x, y in pts:
                if not (-0.001 <= x <= w + 0.001 and -h - 0.001 <= y <= 0.001):
                    problems.append(f"{layer}: point ({x}, {y}) lies outside the page 0..{w} x -{h}..0")
                    break
    for p in problems:
        print(p)
    print(f"compared {compared} paths (largest difference {worst:.4f} mm), {len(strokes)} label strokes, "
          f"{len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
