"""What the corpus sweeps (label_sweep.py, net_sweep.py) share: which foldkit and corpus they run on, and
the corpus files they take."""
import glob
import os


def foldkit_and_corpus(args, tool):
    """FOLDKIT and CORPUS from the positional arguments (defaults: build/cli/foldkit, ../shared/meshes), or
    None after saying the sweep is skipped, as a user's clone has no corpus beside it."""
    foldkit = args[0] if len(args) > 0 else 'build/cli/foldkit'
    corpus = args[1] if len(args) > 1 else '../shared/meshes'
    if not os.path.isdir(corpus):
        print(f'{tool}: no corpus at {corpus}: skipped')
        return None
    return foldkit, corpus


def corpus_files(corpus, keep, extensions=('obj',)):
    """The low-poly models, then the corpus meshes with the given extensions that `keep(path)` admits,
    each group sorted by name."""
    files = sorted(glob.glob(os.path.join(corpus, 'lowpoly', '*.obj')))
    found = [f for ext in extensions for f in glob.glob(os.path.join(corpus, '*.' + ext))]
    return files + [f for f in sorted(found) if keep(f)]
