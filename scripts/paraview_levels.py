"""Shows an mrsim run in ParaView with the object drawn once, each part by the level that
simulates it, coloured by level; the skin (translucent) and the tools on top (issue 19 point 2,
docs/output.md "ParaView").

    pvbatch  scripts/paraview_levels.py OUTDIR [--time T] [--png FILE] [--state FILE] [--tets]
    pvpython scripts/paraview_levels.py OUTDIR --state levels.pvsm    # then File > Load State

Default: the finest level's block coloured by its cell array `simulated_by` (the level that
simulates most of each tet): every part of the object once, the volume exactly the object's.
--tets: each level's own tets where it simulates at least half of them (Threshold on the cell
array `simulated` >= 0.5), coloured by level: the coarse tets themselves (the levels are
independent meshes whose hulls differ, so they overlap a little at the borders).
--time: the simulated time shown (default: the middle of the run). --png: writes a screenshot
(default OUTDIR/levels.png); --state: writes a ParaView state file that reopens this view.

Needs ParaView's Python (pvpython / pvbatch). On Debian its module conflicts with
python3-vtk9, which the build needs; unpack it beside instead (README "ParaView"):
    apt-get download paraview python3-paraview && dpkg-deb -x ... (or install paraview on a
    machine that does not build mrsim).
Exit codes: 0 written, 2 the run folder cannot be read.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

# One colour per level, coarse to fine (the same as scripts/plot_run.py and render_frames.py).
LEVEL_COLOURS = [(0.12, 0.47, 0.71), (1.0, 0.5, 0.05), (0.17, 0.63, 0.17), (0.84, 0.15, 0.16),
                 (0.58, 0.4, 0.74), (0.55, 0.34, 0.29), (0.89, 0.47, 0.76)]


def frames_of(outdir):
    """[(time, vtm path)] from frames.pvd, and the block names of the first frame."""
    pvd = os.path.join(outdir, "frames.pvd")
    try:
        root = ET.parse(pvd).getroot()
        frames = [(float(d.get("timestep")), os.path.join(outdir, d.get("file")))
                  for d in root.iter("DataSet")]
        blocks = [b.get("name") for b in ET.parse(frames[0][1]).getroot().iter("DataSet")]
    except (OSError, ET.ParseError, IndexError, TypeError, ValueError) as e:
        print("error: %s: not an mrsim run folder with frames (%s)" % (outdir, e), file=sys.stderr)
        sys.exit(2)
    return frames, blocks


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--time", type=float)
    ap.add_argument("--png")
    ap.add_argument("--state")
    ap.add_argument("--tets", action="store_true")
    return ap.parse_args()


def level_block(pv, reader, name):
    return pv.MergeBlocks(Input=pv.ExtractBlock(Input=reader, Selectors=["/Root/" + name]))


def show_owner_view(pv, reader, view, finest, levels):
    """The finest level coloured by simulated_by (categorical)."""
    display = pv.Show(level_block(pv, reader, finest), view)
    pv.ColorBy(display, ("CELLS", "simulated_by"))
    lut = pv.GetColorTransferFunction("simulated_by")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = sum([[str(l), "level %d" % l] for l in range(len(levels))], [])
    lut.IndexedColors = sum([list(LEVEL_COLOURS[l % 7]) for l in range(len(levels))], [])
    display.SetScalarBarVisibility(view, True)


def show_tets_view(pv, reader, view, levels):
    """Each level's tets where it simulates at least half, in the level's colour."""
    for l, name in enumerate(levels):
        part = pv.Threshold(Input=level_block(pv, reader, name), Scalars=["CELLS", "simulated"],
                            LowerThreshold=0.5, UpperThreshold=1.0)
        display = pv.Show(part, view)
        display.ColorArrayName = ['POINTS', '']
        display.DiffuseColor = list(LEVEL_COLOURS[l % 7])
        display.AmbientColor = list(LEVEL_COLOURS[l % 7])


def main():
    args = parse_args()
    frames, blocks = frames_of(args.outdir)
    levels = [b for b in blocks if b.startswith("level_")]
    if not levels:
        print("error: %s: the frames have no level blocks" % args.outdir, file=sys.stderr)
        return 2
    import paraview.simple as pv  # after the argument checks: --help works without ParaView
    reader = pv.PVDReader(FileName=os.path.join(args.outdir, "frames.pvd"))
    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1200, 800]
    view.OrientationAxesVisibility = 1
    time = args.time if args.time is not None else frames[len(frames) // 2][0]
    view.ViewTime = time
    pv.GetAnimationScene().AnimationTime = time
    if args.tets:
        show_tets_view(pv, reader, view, levels)
    else:
        show_owner_view(pv, reader, view, levels[-1], levels)
    if "surface" in blocks:
        skin = pv.Show(level_block(pv, reader, "surface"), view)
        skin.ColorArrayName = ['POINTS', '']
        skin.Opacity = 0.25
    if "tool" in blocks:
        tool = pv.Show(level_block(pv, reader, "tool"), view)
        tool.ColorArrayName = ['POINTS', '']
        tool.DiffuseColor = [0.6, 0.6, 0.6]
    view.ResetCamera()
    png = args.png or os.path.join(args.outdir, "levels.png")
    pv.SaveScreenshot(png, view, ImageResolution=[1200, 800])
    print(png)
    if args.state:
        pv.SaveState(args.state)
        print(args.state)
    return 0


if __name__ == "__main__":
    code = main()
    # Leave without ParaView's teardown: under Xvfb (a machine without a display) it fails on
    # the GL context after everything is written (X error GLXBadContext, exit 1).
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
