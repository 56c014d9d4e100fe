#!/usr/bin/env python3
"""A lower bound on the seam labels that cannot sit clear of every line, per mesh at a model size: what
no cut tree and no label placement can beat, because the faces are too small for the numbers.

A label of cap height H (default 2 mm) lifted G (0.5 mm) off its edge and kept C (0.25 mm) clear of
other lines needs, inside the triangle on its side, a width of w + 2C at a height of G + H + C above the
edge: the triangle narrows linearly from the edge to its apex. A side may instead carry its label on a
glue tab, which needs the edge long enough for the label between the tab's steep ends and the tab wide
enough (at most TAB_SHARE of the edge). A seam is labellable when both of its sides are, at most one of
them on a tab. A closed mesh of genus g cut into P parts has V - 2 + 2g + P seams whatever the cut tree
(E - F + P), and the cuts of a one-piece unfolding of a closed mesh reach every vertex (a vertex with no
cut edge would keep its faces closed around it). So when the labellable edges leave the vertices in K
groups, at least K - 1 seams are not labellable, each with a label that has no clear spot. The bound
takes the shortest label (one digit) and counts one label per such seam: it is loose, never too high.

usage: bench/label_bound.py [CORPUS] [--size MM] [--min-faces N] [--max-faces N]
"""
import glob
import math
import os
import sys

GAP, CLEAR, TAB_SHARE = 0.5, 0.25, 0.45
STEEPEST_SLANT = math.radians(75)  # the steepest tab end the tab planner tries
DIGIT = 0.95  # one digit's advance as a share of the cap height (LabelOptions::char_width)


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'v':
                verts.append(tuple(float(x) for x in p[1:4]))
            elif p[0] == 'f':
                idx = [int(t.split('/')[0]) for t in p[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                for k in range(1, len(idx) - 1):
                    faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def bound(path, size_mm, h):
    verts, faces = read_obj(path)
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    scale = size_mm / max(h_ - l_ for h_, l_ in zip(hi, lo))
    width = DIGIT * h
    lift = GAP + h + CLEAR
    sides = {}
    for f in faces:
        area2 = norm(cross(sub(verts[f[1]], verts[f[0]]), sub(verts[f[2]], verts[f[0]]))) * scale * scale
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            length = norm(sub(verts[b], verts[a])) * scale
            height = area2 / length if length > 0 else 0
            room = length * (1 - lift / height) if height > lift else -1
            sides.setdefault((min(a, b), max(a, b)), []).append((room >= width + 2 * CLEAR, length))
    group = list(range(len(verts)))

    def find(x):
        while group[x] != x:
            group[x] = group[group[x]]
            x = group[x]
        return x

    for (a, b), ss in sides.items():
        if len(ss) != 2:
            continue
        length = ss[0][1]
        tab = TAB_SHARE * length >= lift and length - 2 * lift / math.tan(STEEPEST_SLANT) >= width + 2 * CLEAR
        face_a, face_b = ss[0][0], ss[1][0]
        if (face_a and face_b) or (tab and (face_a or face_b)):
            group[find(a)] = find(b)
    used = {v for f in faces for v in f}
    groups = len({find(v) for v in used})
    v, e, fcount = len(used), len(sides), len(faces)
    genus = max(0, (2 - (v - e + fcount)) // 2)
    seams = v - 2 + 2 * genus + 1
    return fcount, seams, groups - 1


def main(argv):
    corpus = next((a for a in argv if not a.startswith('--') and os.path.isdir(a)), '../shared/meshes')
    opt = lambda name, default: float(argv[argv.index(name) + 1]) if name in argv else default
    size, h = opt('--size', 150), opt('--label-min', 2)
    lo, hi = opt('--min-faces', 350), opt('--max-faces', 500)
    if not os.path.isdir(corpus):
        print(f'label_bound: no corpus at {corpus}: skipped')
        return 0
    print('%-28s %5s %5s %9s %8s' % ('mesh', 'faces', 'seams', 'unclear>=', 'share>='))
    total_labels = total_bad = 0
    for path in sorted(glob.glob(os.path.join(corpus, '*.obj'))):
        faces, seams, bad = bound(path, size, h)
        if not lo <= faces <= hi:
            continue
        total_labels += 2 * seams
        total_bad += bad
        print('%-28s %5d %5d %9d %7.1f%%' % (os.path.basename(path), faces, seams, bad, 100 * bad / (2 * seams)))
    if total_labels:
        print('all: at least %d of %d labels (%.1f%%) have no clear spot at %g mm' %
              (total_bad, total_labels, 100 * total_bad / total_labels, size))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
