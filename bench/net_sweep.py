#!/usr/bin/env python3
"""The parts over the corpus, checked by the independent net check (tests/tools/net_check.py): per mesh
and size, the parts `foldkit unfold --size S --paper A4 -o net.obj` writes (the parts `make` lays out),
whether every one is congruent, unmirrored, overlap-free, joined only by real folds, keeps every flat
polygon whole and fits the room it was cut for. The runs of `foldkit bench --layout`: every mesh of the
corpus up to --max-faces (default 1,000) and lowpoly/, at 150 and 250 mm.

usage: bench/net_sweep.py [FOLDKIT] [CORPUS] [--max-faces N]
       (defaults: build/cli/foldkit, ../shared/meshes; Debian's python3 with python3-shapely)
Exit 0 when every run passes, 1 when one fails.
"""
import json
import os
import subprocess
import sys
import tempfile

from corpus import corpus_files, foldkit_and_corpus

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK = os.path.join(HERE, '..', 'tests', 'tools', 'net_check.py')
SIZES_MM = (150, 250)


def faces_of(path):
    with open(path, errors='replace') as f:
        if path.endswith('.off'):
            words = [w for line in f for w in line.split('#')[0].split()]
            return int(words[2])
        return sum(1 for line in f if line.startswith('f '))


def main(argv):
    max_faces = 1000
    if '--max-faces' in argv:
        i = argv.index('--max-faces')
        max_faces = int(argv[i + 1])
        argv = argv[:i] + argv[i + 2:]
    found = foldkit_and_corpus(argv, 'net_sweep')
    if not found:
        return 0
    foldkit, corpus = found
    files = corpus_files(corpus, lambda f: faces_of(f) <= max_faces, ('obj', 'off'))
    runs = passed = refused = 0
    print('%-34s %5s %4s | %6s %6s %6s %9s  %s' % ('mesh', 'faces', 'size', 'parts', 'folds', 'seams', 'room used',
                                                  'net check'))
    with tempfile.TemporaryDirectory() as out:
        net = os.path.join(out, 'net.obj')
        for f in files:
            name = os.path.relpath(f, corpus)
            for size in SIZES_MM:
                run = subprocess.run([foldkit, 'unfold', f, '--size', f'{size}mm', '--paper', 'A4', '--json', '-q',
                                      '-o', net], capture_output=True, text=True)
                if run.returncode != 0:
                    refused += 1
                    print('%-34s %5s %4d | refused: %s' % (name, '', size, run.stderr.strip()), flush=True)
                    continue
                j = json.loads(run.stdout)
                room = 'x'.join('%.6f' % v for v in j['part_room_mm'])
                check = subprocess.run(['/usr/bin/python3' if os.path.exists('/usr/bin/python3') else 'python3',
                                        CHECK, f, net, '--mm-per-unit', repr(j['scale_mm_per_unit']), '--room', room,
                                        '--json'], capture_output=True, text=True)
                runs += 1
                if check.returncode == 77:
                    print(check.stdout.strip())
                    return 0
                if check.returncode not in (0, 1):
                    print('%-34s %5d %4d | check failed to run: %s' % (name, j['face_count'], size,
                                                                       (check.stdout + check.stderr).strip()))
                    continue
                c = json.loads(check.stdout)
                passed += not c['problems']
                verdict = 'ok' if not c['problems'] else '; '.join(c['problems'][:3])
                print('%-34s %5d %4d | %6d %6d %6d %8.1f%%  %s' % (
                    name, j['face_count'], size, c['pieces'], c.get('folds', 0), c.get('seams', 0),
                    100 * c.get('tightest_room_share', 0), verdict), flush=True)
    print(f'net check: {passed} of {runs} runs pass ({refused} refused: a flat face larger than the room)')
    return 0 if passed == runs else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
