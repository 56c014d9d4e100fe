#!/usr/bin/env python3
"""Renders a DXF to PNG with ezdxf's drawing add-on (needs python3-matplotlib), page frame from the
file's $LIMMIN/$LIMMAX, to look at foldkit's DXF as a CAD reader shows it.
usage: render_dxf.py IN.dxf OUT.png [DPI]"""
import sys

import ezdxf
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from ezdxf.addons.drawing import Frontend, RenderContext  # noqa: E402
from ezdxf.addons.drawing.matplotlib import MatplotlibBackend  # noqa: E402

MM_PER_INCH = 25.4


def main():
    doc = ezdxf.readfile(sys.argv[1])
    lo, hi = doc.header.get("$LIMMIN", (0, -297)), doc.header.get("$LIMMAX", (210, 0))
    w, h = hi[0] - lo[0], hi[1] - lo[1]
    fig = plt.figure(figsize=(w / MM_PER_INCH, h / MM_PER_INCH))
    ax = fig.add_axes([0, 0, 1, 1])
    ctx = RenderContext(doc)
    Frontend(ctx, MatplotlibBackend(ax)).draw_layout(doc.modelspace(), finalize=True)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    fig.savefig(sys.argv[2], dpi=int(sys.argv[3]) if len(sys.argv) > 3 else 150)


if __name__ == "__main__":
    main()
