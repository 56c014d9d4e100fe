#!/usr/bin/env python3
"""Label legibility over the corpus: per mesh, the labels `foldkit make --json` prints and how many of
them cross a cut or fold line or touch another text, at 150 mm on A4 (the issue-12 targets: none on
the low-poly models, at most 2% on the 350-500-face meshes).

usage: bench/label_sweep.py [FOLDKIT] [CORPUS] [-- extra make options]
       (defaults: build/cli/foldkit, ../shared/meshes)
"""
import json
import os
import subprocess
import sys
import tempfile

from corpus import corpus_files, foldkit_and_corpus


def faces_of(path):
    with open(path) as f:
        return sum(1 for line in f if line.startswith('f '))


def main(argv):
    extra = argv[argv.index('--') + 1:] if '--' in argv else []
    args = argv[:argv.index('--')] if '--' in argv else argv
    found = foldkit_and_corpus(args, 'label_sweep')
    if not found:
        return 0
    foldkit, corpus = found
    files = corpus_files(corpus, lambda f: 350 <= faces_of(f) <= 500)
    totals = {'lowpoly': [0, 0], 'mid': [0, 0]}
    print('%-32s %5s %6s %6s %6s %6s' % ('mesh', 'faces', 'labels', 'cross', 'touch', 'share'))
    with tempfile.TemporaryDirectory() as out:
        for f in files:
            run = subprocess.run([foldkit, 'make', f, '--size', '150mm', '--paper', 'A4', '--json', '-q',
                                  '--no-guide', '-o', os.path.join(out, 'sheet.svg')] + extra,
                                 capture_output=True, text=True)
            name = os.path.relpath(f, corpus)
            if run.returncode != 0:
                print('%-32s error: %s' % (name, run.stderr.strip()))
                continue
            j = json.loads(run.stdout)
            labels = j['overall']['label_count']
            bad = j['labels_crossing_lines_count'] + j['labels_touching_count']
            group = totals['lowpoly' if name.startswith('lowpoly') else 'mid']
            group[0] += labels
            group[1] += bad
            print('%-32s %5d %6d %6d %6d %5.1f%%' % (name, j['face_count'], labels, j['labels_crossing_lines_count'],
                                                   j['labels_touching_count'], 100.0 * bad / max(labels, 1)),
                  flush=True)
    for group, (labels, bad) in totals.items():
        print('%s: %d of %d labels cross a line or touch (%.1f%%)' % (
            'low-poly' if group == 'lowpoly' else '350-500 faces', bad, labels, 100.0 * bad / max(labels, 1)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
