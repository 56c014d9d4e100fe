#!/usr/bin/env python3
"""Sheets that Blender's "Export Paper Model" add-on (the peer, Debian's blender package) needs for the
runs of `foldkit bench --layout`: each mesh at 150 and 250 mm (its largest dimension) on A4 with foldkit's
10 mm margin, islands limited to the page as the add-on's "Limit Island Size" does, tabs and numbers on.

The add-on limits islands to the size its scene settings name, without its margins, tabs and island
titles, and then refuses islands that do not fit the printable area with them; so that size is the
printable area less 20 mm each way (tabs of 5 mm on both sides, a title of 6 mm; 170 x 257 mm on A4).
Its auto-scale is off, so the model keeps the asked size.

usage: bench/blender_sheets.py [CORPUS] [--max-faces N] [--bench-json FILE]
       (defaults: ../shared/meshes, 1000; FILE: `foldkit bench --layout --json` output to set beside)
Prints CSV: mesh,face_count,size_mm,blender_sheet_count,blender_s,foldkit_sheet_count,error; then totals.
Needs blender (apt-get install blender) and pdfinfo (poppler-utils). Run under Blender it exports one
mesh: blender -b --factory-startup --python bench/blender_sheets.py -- MESH SIZE_MM OUT.pdf
"""
import csv
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

SIZES_MM = (150, 250)
MARGIN_M = 0.010
TAB_M = 0.005
CAGE_SLACK_M = 0.020  # tabs on both sides and the island's title
A4_M = (0.210, 0.297)
BLENDER_TIMEOUT_S = 900


def export_in_blender(mesh, size_mm, out):
    import addon_utils
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("io_export_paper_model", default_set=True)
    bpy.ops.wm.obj_import(filepath=mesh)
    ob = bpy.context.selected_objects[0]
    bpy.context.view_layer.objects.active = ob
    s = size_mm / 1000.0 / max(ob.dimensions)
    ob.scale = tuple(c * s for c in ob.scale)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    pm = bpy.context.scene.paper_model
    pm.use_auto_scale = False
    pm.limit_by_page = True
    pm.output_size_x = A4_M[0] - 2 * MARGIN_M - CAGE_SLACK_M
    pm.output_size_y = A4_M[1] - 2 * MARGIN_M - CAGE_SLACK_M
    bpy.ops.export_mesh.paper_model(filepath=out, file_format='PDF', page_size_preset='A4', scale=1,
                                    output_margin=MARGIN_M, sticker_width=TAB_M)


def faces_of(path):
    with open(path) as f:
        return sum(1 for line in f if line.startswith('f '))


def blender_run(mesh, size_mm):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'net.pdf')
        start = time.monotonic()
        try:
            run = subprocess.run(['blender', '-b', '--factory-startup', '--python', os.path.abspath(__file__),
                                  '--', mesh, str(size_mm), out], capture_output=True, text=True,
                                 timeout=BLENDER_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            return 0, time.monotonic() - start, f'no result within {BLENDER_TIMEOUT_S} s'
        seconds = time.monotonic() - start
        if not os.path.exists(out):
            log = run.stdout + run.stderr
            refusal = re.search(r"UnfoldError: \('(.*?)(?: Export failed|',)", log)
            error = re.search(r'Error: (.*)', log)
            text = refusal.group(1) if refusal else error.group(1) if error else 'no output'
            return 0, seconds, ' '.join(text.replace('\\n', ' ').split())
        info = subprocess.run(['pdfinfo', out], capture_output=True, text=True).stdout
        return int(re.search(r'Pages:\s+(\d+)', info).group(1)), seconds, ''


def main(argv):
    args = list(argv)
    max_faces, bench_json = 1000, None
    if '--max-faces' in args:
        i = args.index('--max-faces')
        max_faces = int(args[i + 1])
        del args[i:i + 2]
    if '--bench-json' in args:
        i = args.index('--bench-json')
        bench_json = args[i + 1]
        del args[i:i + 2]
    corpus = args[0] if args else '../shared/meshes'
    if not os.path.isdir(corpus):
        print(f'blender_sheets: no corpus at {corpus}: skipped')
        return 0
    missing = [tool for tool in ('blender', 'pdfinfo') if not shutil.which(tool)]
    if missing:
        print(f'blender_sheets: {" and ".join(missing)} not found (apt-get install blender poppler-utils)',
              file=sys.stderr)
        return 1
    foldkit = {}
    if bench_json:
        for row in json.load(open(bench_json))['rows']:
            if 'sheet_count' in row:
                foldkit[(row['mesh'], float(row['size_mm']))] = row['sheet_count']
    files = sorted(glob.glob(os.path.join(corpus, '*.obj')) + glob.glob(os.path.join(corpus, 'lowpoly', '*.obj')))
    out = csv.writer(sys.stdout, lineterminator='\n')
    out.writerow(['mesh', 'face_count', 'size_mm', 'blender_sheet_count', 'blender_s', 'foldkit_sheet_count',
                  'error'])
    both = [0, 0]  # sheets over the runs both finished: Blender, foldkit
    for path in files:
        faces = faces_of(path)
        if faces > max_faces:
            continue
        name = os.path.relpath(path, corpus)
        for size in SIZES_MM:
            sheets, seconds, error = blender_run(path, size)
            ours = foldkit.get((name, float(size)), '')
            if sheets and ours != '':
                both[0] += sheets
                both[1] += ours
            out.writerow([name, faces, size, sheets, f'{seconds:.1f}', ours, error])
            sys.stdout.flush()
    if bench_json:
        print(f'# runs both finished: Blender {both[0]} sheets, foldkit {both[1]}')
    return 0


def in_blender():
    try:
        import bpy  # noqa: F401
        return True
    except ImportError:
        return False


if __name__ == '__main__':
    if in_blender():
        a = sys.argv[sys.argv.index('--') + 1:]
        export_in_blender(a[0], float(a[1]), a[2])
    else:
        sys.exit(main(sys.argv[1:]))
