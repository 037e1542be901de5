#!/usr/bin/python3
"""Render an mrsim run (its frames.pvd) to PNG frames, headless, for movies and figures.

    xvfb-run -a /usr/bin/python3 scripts/render_frames.py RUN_DIR [-o OUT_DIR] [--color level]

Only `vtkmodules` and numpy are used, so the script runs both with Debian's python3-vtk9
(/usr/bin/python3) and with ParaView's pvpython. See --help and docs/output.md for the files read.

Exit codes: 0 done, 2 bad options, an unreadable run folder, or no way to render (no display).
"""
import argparse
import colorsys
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import (reference, vtkLogger, vtkLookupTable, vtkOutputWindow,
                                      vtkStringOutputWindow)
from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkCompositeDataSet, vtkPolyData,
                                           vtkStaticCellLocator, vtkUnstructuredGrid)
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)

# Level colours with well separated hues (coarse = blue … fine = red), so a level stays
# recognisable under shading and a test can tell the levels apart by hue alone.
LEVEL_COLORS = [(0.23, 0.42, 0.85), (0.20, 0.70, 0.30), (0.98, 0.60, 0.10), (0.85, 0.15, 0.20),
                (0.60, 0.30, 0.80), (0.10, 0.75, 0.80), (0.90, 0.85, 0.15), (0.55, 0.35, 0.20)]
STATUS_COLORS = [(0.80, 0.80, 0.80), (0.98, 0.60, 0.10), (0.85, 0.15, 0.20)]
STATUS_NAMES = ["inactive", "ghost", "active"]
TOOL_COLOR = (0.55, 0.55, 0.55)
BACKGROUND = (1.0, 1.0, 1.0)
VIEW_ANGLE = 30.0    # degrees, vertical
MARGIN = 1.08        # room around the points the camera frames
LEGEND_WIDTH = 0.16  # share of the image width kept for the legend, on the right
CAMERA_SAMPLES = 12  # frames besides the first whose points the camera frames
# Directions from the focal point to the camera, and the up vector (z is up: gravity is -z).
VIEWS = {"iso": ((-1.0, -1.0, 1.0), (0, 0, 1)), "x": ((1, 0, 0), (0, 0, 1)),
         "y": ((0, -1, 0), (0, 0, 1)), "z": ((0, 0, 1), (0, 1, 0))}
NO_DISPLAY = ("no display: run it under xvfb-run -a %s (Debian package xvfb)"
              % " ".join([sys.executable] + sys.argv))


class RunError(Exception):
    """A problem the user can fix (missing folder, corrupt file, no display): exit 2."""


# ----------------------------------------------------------------------------- options

def parse_size(text):
    """'960x540' -> (960, 540); argparse turns the ValueError into a usage error (exit 2)."""
    w, h = (int(v) for v in text.lower().split("x"))
    if not (16 <= w <= 8192 and 16 <= h <= 8192):
        raise ValueError(text)
    return w, h


def parse_args(argv):
    ap = argparse.ArgumentParser(
        description="Render the frames of an mrsim run (RUN_DIR/frames.pvd) to PNG files "
                    "OUT_DIR/frame_NNNNNN.png (NNNNNN: the run's frame number), with a fixed "
                    "camera. Needs an X display: run it under `xvfb-run -a` on a headless machine.")
    ap.add_argument("run_dir", metavar="RUN_DIR", help="output folder of `mrsim run`")
    ap.add_argument("-o", "--out", metavar="OUT_DIR",
                    help="where the PNGs go (default RUN_DIR/render)")
    ap.add_argument("--color", choices=["level", "status", "displacement", "time_level"],
                    default="level",
                    help="level (default): where each level simulates, on the object's skin when "
                         "the run has one (runs with tools), else as each level's simulated tets "
                         "with their edges; status: one level (--level) by point status; "
                         "displacement: the finest level by |u|; time_level: like level, by the "
                         "finest time level of each tet")
    ap.add_argument("--level", type=int, metavar="K",
                    help="level shown by --color status (default: the finest) and by "
                         "--color time_level (default: the simulated tets of every level)")
    ap.add_argument("--frames", default="all", metavar="all|FIRST:LAST:STEP",
                    help="frame numbers to render, LAST included, each part optional "
                         "(0:50:5, 20:, ::2, 25); default all")
    ap.add_argument("--size", type=parse_size, default=(960, 540), metavar="WxH",
                    help="image size in pixels (default 960x540)")
    ap.add_argument("--view", choices=sorted(VIEWS), default="iso",
                    help="camera direction: iso, or along the x, y or z axis (default iso)")
    ap.add_argument("--offscreen", action="store_true",
                    help="render off screen (no window). Debian's VTK 9.1 still needs an X "
                         "server for it (xvfb-run); a VTK built with EGL/OSMesa does not")
    ap.add_argument("--tets", action="store_true",
                    help="--color level/time_level: draw each level's simulated tets even when "
                         "the run has a skin (block surface), which is drawn by default")
    ap.add_argument("--no-tools", action="store_true", help="do not draw the tools")
    ap.add_argument("-q", "--quiet", action="store_true", help="print only errors")
    return ap.parse_args(argv)


def parse_frame_spec(spec):
    """'all' | 'FIRST:LAST:STEP' | 'N' -> (first, last, step); last is inclusive, None = open."""
    if spec == "all":
        return 0, None, 1
    parts = spec.split(":")
    if len(parts) > 3:
        raise RunError("--frames %r: expected all or FIRST:LAST:STEP" % spec)
    try:
        vals = [int(p) if p.strip() else None for p in parts]
    except ValueError:
        raise RunError("--frames %r: expected all or FIRST:LAST:STEP (integers)" % spec)
    if len(vals) == 1:
        vals = [vals[0], vals[0], 1]
    first, last, step = (vals + [None])[:3]
    first, step = (0 if first is None else first), (1 if step is None else step)
    if step < 1 or first < 0 or (len(parts) == 1 and parts[0].strip() == ""):
        raise RunError("--frames %r: FIRST must be >= 0 and STEP >= 1" % spec)
    return first, last, step


# ----------------------------------------------------------------------------- reading

def read_series(run_dir):
    """[(time, frame number, vtm path)] from frames.pvd, in order; RunError if unusable."""
    if not os.path.isdir(run_dir):
        raise RunError("run folder %s does not exist" % run_dir)
    pvd = os.path.join(run_dir, "frames.pvd")
    if not os.path.isfile(pvd):
        raise RunError("%s is missing: not an mrsim run folder?" % pvd)
    try:
        entries = list(ET.parse(pvd).getroot().iter("DataSet"))
        series = []
        for d in entries:
            path = os.path.join(run_dir, d.get("file"))
            number = int(os.path.basename(path).split("_")[-1].split(".")[0])
            series.append((float(d.get("timestep")), number, path))
    except (ET.ParseError, TypeError, ValueError, IndexError) as e:
        raise RunError("%s is malformed: %s" % (pvd, e))
    if not series:
        raise RunError("%s lists no frame" % pvd)
    return series


def select_frames(series, spec):
    """The entries of series whose frame number --frames selects; RunError when none is."""
    first, last, step = parse_frame_spec(spec)
    chosen = [e for e in series
              if e[1] >= first and (last is None or e[1] <= last) and (e[1] - first) % step == 0]
    if not chosen:
        raise RunError("--frames %s selects none of the frames %d … %d"
                       % (spec, series[0][1], series[-1][1]))
    return chosen


def read_frame(vtm):
    """{block name: dataset} of one frame. VTK's reader only prints its errors, so they are
    collected here and turned into one RunError naming the file, rather than a blank frame."""
    if not os.path.isfile(vtm):
        raise RunError("%s is missing" % vtm)
    log = vtkStringOutputWindow()
    previous, verbosity = vtkOutputWindow.GetInstance(), vtkLogger.GetCurrentVerbosityCutoff()
    vtkOutputWindow.SetInstance(log)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    try:
        reader = vtkXMLMultiBlockDataReader()
        reader.SetFileName(vtm)
        reader.Update()
        mb = reader.GetOutput()
    finally:
        vtkOutputWindow.SetInstance(previous)
        vtkLogger.SetStderrVerbosity(verbosity)
    text = log.GetOutput()
    if "ERROR" in text:
        lines = [l.strip() for l in text.splitlines() if l.strip()]
        why = [l for l in lines if not l.startswith(("ERROR:", "Warning:"))] or lines
        raise RunError("cannot read %s: %s" % (vtm, why[0][-300:]))
    blocks = {}
    for i in range(mb.GetNumberOfBlocks()):
        meta = mb.GetMetaData(i) if mb.HasMetaData(i) else None
        name = meta.Get(vtkCompositeDataSet.NAME()) if meta else None
        if name and mb.GetBlock(i) is not None:
            blocks[name] = mb.GetBlock(i)
    check_levels(vtm, blocks)
    return blocks


def check_levels(vtm, blocks):
    """The level blocks must be there, tetrahedral and carry `status`: else RunError."""
    levels = level_grids(blocks)
    if not levels:
        raise RunError("cannot read %s: no block level_0" % vtm)
    for k, grid in enumerate(levels):
        if grid.GetNumberOfPoints() == 0 or grid.GetPointData().GetArray("status") is None:
            raise RunError("cannot read %s: block level_%d is empty or has no status" % (vtm, k))
        n_ids = grid.GetCells().GetConnectivityArray().GetNumberOfValues()
        if n_ids != 4 * grid.GetNumberOfCells():
            raise RunError("cannot read %s: block level_%d is not made of tetrahedra" % (vtm, k))


def level_grids(blocks):
    """[level_0, level_1, …] up to the first missing one: blocks are looked up by name."""
    out = []
    while "level_%d" % len(out) in blocks:
        out.append(blocks["level_%d" % len(out)])
    return out


def point_array(grid, name):
    array = grid.GetPointData().GetArray(name)
    if array is None:
        raise RunError("a level block has no point array %s" % name)
    return vtk_to_numpy(array)


def tets(grid):
    return vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)


# ----------------------------------------------------------------------------- geometry

def simulated_cells(grid):
    """Mask of the tets a level simulates: all four points active or ghost, at least one
    active. The 'at least one active' matters: a level whose points are all ghosts (e.g. the
    coarse level once everything is split) carries no simulation and would otherwise be drawn
    over the finer levels."""
    status = point_array(grid, "status")[tets(grid)]
    return (status >= 1).all(axis=1) & (status == 2).any(axis=1)


def surface(grid, mask=None, cell_values=None):
    """Outer surface of the masked tets of grid (all when mask is None) as polydata, with the
    optional per-tet values as cell scalars and the point arrays carried over."""
    conn = tets(grid) if mask is None else tets(grid)[mask]
    ug = vtkUnstructuredGrid()
    ug.SetPoints(grid.GetPoints())
    ug.GetPointData().ShallowCopy(grid.GetPointData())
    cells = vtkCellArray()
    offsets = np.arange(0, 4 * len(conn) + 1, 4, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
                  numpy_to_vtkIdTypeArray(conn.astype(np.int64).ravel(), deep=1))
    ug.SetCells(10, cells)  # VTK_TETRA
    if cell_values is not None:
        values = numpy_to_vtk(np.ascontiguousarray(cell_values, dtype=np.float64), deep=1)
        values.SetName("value")
        ug.GetCellData().SetScalars(values)
    geometry = vtkGeometryFilter()
    geometry.SetInputData(ug)
    geometry.Update()
    return geometry.GetOutput()


def surface_actor(poly, color=None, lut=None, scalar_range=None, edges=True, on_top=0):
    """An actor for a surface: flat colour, or scalars through lut. on_top > 0 pushes it in
    front of coincident faces of other actors (nested levels share their boundary)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    if lut is None:
        mapper.ScalarVisibilityOff()
    else:
        mapper.SetLookupTable(lut)
        mapper.UseLookupTableScalarRangeOn() if scalar_range is None else \
            mapper.SetScalarRange(*scalar_range)
    mapper.SetRelativeCoincidentTopologyPolygonOffsetParameters(-2.0 * on_top, -20.0 * on_top)
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    if color is not None:
        prop.SetColor(*color)
        prop.SetEdgeColor(*(0.45 * c for c in color))
    else:
        prop.SetEdgeColor(0.25, 0.25, 0.25)
    prop.SetEdgeVisibility(edges)
    prop.SetLineWidth(1.0)
    prop.SetAmbient(0.2)
    prop.SetDiffuse(0.8)
    prop.SetSpecular(0.15)
    return actor


# ----------------------------------------------------------------------------- colourings

def categorical_lut(colors, names, first=0):
    """Lookup table with one colour per integer value first, first+1, …, and its legend text."""
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(len(colors))
    lut.SetTableRange(first, first + len(colors) - 1)
    for i, (c, n) in enumerate(zip(colors, names)):
        lut.SetTableValue(i, c[0], c[1], c[2], 1.0)
        lut.SetAnnotation(first + i, n)
    lut.IndexedLookupOn()
    lut.Build()
    return lut


def bind_skin(blocks):
    """For each level, the tet holding each skin vertex at rest (the nearest tet when the
    vertex lies outside that level's mesh), like mrsim's own skin binding. Computed once from
    the first frame: rest positions do not change. None when the run has no skin."""
    skin = blocks.get("surface")
    if (skin is None or skin.GetNumberOfPoints() == 0
            or skin.GetPointData().GetArray("displacement") is None):
        return None
    rest = vtk_to_numpy(skin.GetPoints().GetData()) - point_array(skin, "displacement")
    bound = []
    for grid in level_grids(blocks):
        ug = vtkUnstructuredGrid()
        ug.DeepCopy(grid)
        at_rest = vtk_to_numpy(grid.GetPoints().GetData()) - point_array(grid, "displacement")
        ug.GetPoints().SetData(numpy_to_vtk(np.ascontiguousarray(at_rest), deep=1))
        locator = vtkStaticCellLocator()
        locator.SetDataSet(ug)
        locator.BuildLocator()
        bound.append(np.array([locate(locator, x) for x in rest], dtype=np.int64))
    return bound


def locate(locator, x):
    """Tet holding x, else the nearest one."""
    cell = locator.FindCell(x)
    if cell >= 0:
        return cell
    closest, cell, sub, dist2 = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
    locator.FindClosestPoint(x, closest, cell, sub, dist2)
    return int(cell)


def skin_owner(levels, bound):
    """Per skin vertex, the level that simulates the most of its place: the one whose bound tet
    has the most active points (under the energy coupling a tet with k active points is k/4
    simulated by its level), the finer on a tie. The skin's own `level` array instead names
    the finest level whose tet has no inactive point, which counts ghost scaffolding: on
    liver_probe it paints wide level 1 and 2 bands where those levels have 1 to 3 active points."""
    counts = np.stack([(point_array(g, "status")[tets(g)[b]] == 2).sum(axis=1)
                       for g, b in zip(levels, bound)])
    return len(levels) - 1 - np.argmax(counts[::-1], axis=0)


def skin_scene(blocks, style, vertex_values):
    """The skin with each triangle coloured by the largest value of its vertices."""
    skin = blocks["surface"]
    triangles = vtk_to_numpy(skin.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    poly = vtkPolyData()
    poly.ShallowCopy(skin)
    values = numpy_to_vtk(np.ascontiguousarray(vertex_values[triangles].max(axis=1),
                                               dtype=np.float64), deep=1)
    poly.GetCellData().SetScalars(values)
    # No edges: they would be the finest level's triangles everywhere, saying nothing about
    # the levels, and they triple the size of the PNG.
    return [surface_actor(poly, lut=style["lut"], edges=False)], style["lut"]


def use_skin(blocks, style):
    return style.get("skin") is not None and "surface" in blocks and not style["tets"]


def level_scene(blocks, style):
    """Colour by the level that simulates each place. With a skin (runs with tools) the skin,
    by skin_owner: the levels of a hierarchy need not be nested (the liver's coarse levels are
    crude hulls that cut through the organ), so only the skin shows the real shape. Without a
    skin, or with --tets, each level's simulated tets in the level's colour, the finer levels
    in front where faces coincide."""
    levels = level_grids(blocks)
    if use_skin(blocks, style):
        return skin_scene(blocks, style, skin_owner(levels, style["skin"]))
    actors = []
    for k, grid in enumerate(levels):
        mask = simulated_cells(grid)
        if mask.any():
            color = LEVEL_COLORS[k % len(LEVEL_COLORS)]
            actors.append(surface_actor(surface(grid, mask), color=color, on_top=k + 1))
    return actors, style["lut"]


def time_level_scene(blocks, style):
    """Each tet by the finest time level among its points (ghosts carry -1: a tet steps with
    its finest integrated point). One level's block with --level; else the skin with each
    vertex taking its owner's tet (see level_scene); else every level's simulated tets."""
    levels = level_grids(blocks)
    if style["level"] is None and use_skin(blocks, style):
        owner = skin_owner(levels, style["skin"])
        per_level = [point_array(g, "time_level")[tets(g)[b]].max(axis=1)
                     for g, b in zip(levels, style["skin"])]
        values = np.choose(owner, per_level)
        return skin_scene(blocks, style, values)
    chosen = range(len(levels)) if style["level"] is None else [style["level"]]
    actors = []
    for k in chosen:
        grid = levels[k]
        mask = simulated_cells(grid) if style["level"] is None else None
        if mask is None or mask.any():
            conn = tets(grid) if mask is None else tets(grid)[mask]
            values = point_array(grid, "time_level")[conn].max(axis=1)
            poly = surface(grid, mask, values)
            actors.append(surface_actor(poly, lut=style["lut"], on_top=k + 1))
    return actors, style["lut"]


def status_scene(blocks, style):
    """The chosen level's whole mesh (every level holds the whole deformed body), by status."""
    levels = level_grids(blocks)
    grid = levels[min(style["level"], len(levels) - 1)]
    poly = surface(grid)
    poly.GetPointData().SetActiveScalars("status")
    return [surface_actor(poly, lut=style["lut"])], style["lut"]


def displacement_scene(blocks, style):
    """The finest level by |u|, with the colour range of the whole selection (fixed)."""
    grid = level_grids(blocks)[-1]
    poly = surface(grid, cell_values=None)
    mag = np.linalg.norm(point_array(grid, "displacement"), axis=1)
    arr = numpy_to_vtk(np.ascontiguousarray(mag), deep=1)
    arr.SetName("|u|")
    poly.GetPointData().SetScalars(arr)
    return [surface_actor(poly, lut=style["lut"], scalar_range=style["range"], edges=False)], \
        style["lut"]


SCENES = {"level": level_scene, "status": status_scene,
          "displacement": displacement_scene, "time_level": time_level_scene}


def chosen_level(args, n_levels):
    """--level, checked against the run's levels; the finest when not given."""
    level = n_levels - 1 if args.level is None else args.level
    if not 0 <= level < n_levels:
        raise RunError("--level %d: the run has levels 0 … %d" % (level, n_levels - 1))
    return level


def ramp(n):
    """n colours from blue (coarse steps) to red (fine steps)."""
    return [colorsys.hsv_to_rgb(0.667 * (1.0 - i / max(n - 1, 1)), 0.85, 0.9) for i in range(n)]


def colour_style(args, series, first_blocks):
    """What stays the same across frames: lookup table, value range, chosen level, so that a
    colour means the same thing in every frame of the movie."""
    n_levels = len(level_grids(first_blocks))
    if args.color == "level":
        colors = [LEVEL_COLORS[k % len(LEVEL_COLORS)] for k in range(n_levels)]
        return {"lut": categorical_lut(colors, ["level %d" % k for k in range(n_levels)]),
                "title": "level", "tets": args.tets,
                "skin": None if args.tets else bind_skin(first_blocks)}
    level = chosen_level(args, n_levels)
    if args.color == "status":
        return {"lut": categorical_lut(STATUS_COLORS, STATUS_NAMES), "level": level,
                "title": "status, level %d" % level}
    if args.color == "time_level":
        top = max(int(point_array(g, "time_level").max())
                  for e in series for g in level_grids(read_frame(e[2])))
        colors = [(0.7, 0.7, 0.7)] + ramp(top + 1)
        names = ["not integrated"] + ["time level %d" % k for k in range(top + 1)]
        return {"lut": categorical_lut(colors, names, first=-1), "title": "time level",
                "level": None if args.level is None else level, "tets": args.tets,
                "skin": None if args.tets or args.level is not None else bind_skin(first_blocks)}
    top = max(float(np.linalg.norm(point_array(level_grids(read_frame(e[2]))[-1],
                                               "displacement"), axis=1).max()) for e in series)
    lut = vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.Build()
    return {"lut": lut, "range": (0.0, top if top > 0 else 1.0), "title": "|u| (m)"}


# ----------------------------------------------------------------------------- rendering

def legend(lut, title, categorical):
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetPosition(0.88, 0.15)
    bar.SetPosition2(0.11, 0.7)
    bar.SetBarRatio(0.25)
    bar.SetDrawAnnotations(categorical)
    bar.SetDrawTickLabels(not categorical)
    bar.SetLabelFormat("%.3g")
    bar.UnconstrainedFontSizeOn()
    bar.SetVerticalTitleSeparation(8)
    for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty(),
                 bar.GetAnnotationTextProperty()):
        prop.SetColor(0.1, 0.1, 0.1)
        prop.ShadowOff()
        prop.ItalicOff()
        prop.BoldOff()
        prop.SetFontSize(14)
    return bar


def corner_text(text, x, y, size, right=False):
    actor = vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetFontSize(size)
    prop.SetColor(0.1, 0.1, 0.1)
    prop.SetFontFamilyToCourier() if not right else prop.SetFontFamilyToArial()
    if right:
        prop.SetJustificationToRight()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.GetPositionCoordinate().SetValue(x, y)
    return actor


def tool_actor(blocks):
    tool = blocks.get("tool")
    if tool is None or tool.GetNumberOfCells() == 0:
        return None
    return surface_actor(tool, color=TOOL_COLOR, edges=False)


def frame_points(blocks):
    """Points of the levels and tools of a frame: what the camera must hold."""
    names = [n for n in sorted(blocks) if n.startswith("level_") or n == "tool"]
    return np.vstack([vtk_to_numpy(blocks[n].GetPoints().GetData()) for n in names
                      if blocks[n].GetNumberOfPoints()])


def camera_points(series, first_blocks):
    """Points the fixed camera frames: those of the first frame and of a few frames spread over
    the run up to the last one, so that a body that sags or a tool that withdraws stays in the
    picture. Independent of --frames and --no-tools: one run, one camera for a given view."""
    picks = sorted(set(np.linspace(1, len(series) - 1, min(CAMERA_SAMPLES, len(series) - 1),
                                   dtype=int).tolist())) if len(series) > 1 else []
    points = [frame_points(first_blocks)]
    points += [frame_points(read_frame(series[i][2])) for i in picks]
    return np.vstack(points)


def place_camera(renderer, points, view, aspect):
    """Fixed camera looking at the points from the chosen direction, at the nearest distance
    where all of them, with a margin, fit in the part of the image left of the legend."""
    center = 0.5 * (points.min(axis=0) + points.max(axis=0))
    direction, up = (np.array(v, dtype=float) for v in VIEWS[view])
    direction /= np.linalg.norm(direction)
    right = np.cross(direction, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, direction)
    rel = points - center
    tan_half = math.tan(math.radians(VIEW_ANGLE / 2.0)) / MARGIN
    usable = aspect * (1.0 - LEGEND_WIDTH)
    need = rel @ direction + np.maximum(np.abs(rel @ true_up) / tan_half,
                                        np.abs(rel @ right) / (tan_half * usable))
    cam = renderer.GetActiveCamera()
    cam.SetViewAngle(VIEW_ANGLE)
    cam.SetFocalPoint(*center)
    cam.SetPosition(*(center + max(float(need.max()), 1e-9) * direction))
    cam.SetViewUp(*up)
    cam.SetWindowCenter(LEGEND_WIDTH, 0.0)  # shifts the body left, off the legend
    renderer.ResetCameraClippingRange()


def make_window(size, offscreen):
    window = vtkRenderWindow()
    window.SetSize(*size)
    window.SetOffScreenRendering(1 if offscreen else 0)
    window.SetMultiSamples(8)
    renderer = vtkRenderer()
    renderer.SetBackground(*BACKGROUND)
    window.AddRenderer(renderer)
    return window, renderer


def probe_rendering(offscreen):
    """Check that a window can be drawn, in a forked child: VTK's X window aborts the whole
    process (SIGABRT, no exception) when there is no X server, even off screen, because
    Debian's VTK 9.1 is built with GLX only (no EGL, no OSMesa). A VTK with EGL/OSMesa (some
    pvpython builds) passes the probe without any display."""
    if not hasattr(os, "fork"):
        return
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        try:
            window, _ = make_window((16, 16), offscreen)
            window.SetMultiSamples(0)
            window.Render()
            os._exit(0)
        except BaseException:
            os._exit(3)
    _, status = os.waitpid(pid, 0)
    if os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0:
        return
    display = os.environ.get("DISPLAY")
    kind = vtkRenderWindow().GetClassName()
    if not display:
        raise RunError("%s\n(DISPLAY is not set, and this VTK's %s needs an X server even "
                       "with --offscreen)" % (NO_DISPLAY, kind))
    raise RunError("%s\n(cannot draw a %s window on DISPLAY=%s)" % (NO_DISPLAY, kind, display))


def write_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetCompressionLevel(9)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        raise RunError("cannot write %s" % path)


def render_frame(window, renderer, blocks, time, args, style, title):
    """Replace the props of the scene by those of this frame; the camera is left alone."""
    renderer.RemoveAllViewProps()
    actors, lut = SCENES[args.color](blocks, style)
    tool = None if args.no_tools else tool_actor(blocks)
    for actor in actors + ([tool] if tool else []):
        renderer.AddActor(actor)
    renderer.AddViewProp(legend(lut, style["title"], args.color != "displacement"))
    renderer.AddViewProp(corner_text("t = %.3f s" % time, 0.02, 0.93, 20))
    renderer.AddViewProp(corner_text(title, 0.98, 0.02, 14, right=True))
    renderer.ResetCameraClippingRange()
    window.Render()


def movie_hint(out_dir, numbers):
    """The ffmpeg line for these files: %06d needs consecutive numbers, else a glob."""
    consecutive = numbers == list(range(numbers[0], numbers[0] + len(numbers)))
    src = ("-start_number %d -i %s" % (numbers[0], os.path.join(out_dir, "frame_%06d.png"))
           if consecutive else
           "-pattern_type glob -i '%s'" % os.path.join(out_dir, "frame_*.png"))
    return ("ffmpeg -framerate 25 %s -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 "
            "-pix_fmt yuv420p %s" % (src, os.path.join(out_dir, "movie.mp4")))


def render_run(args):
    series = read_series(args.run_dir)
    chosen = select_frames(series, args.frames)
    first_blocks = read_frame(series[0][2])
    style = colour_style(args, chosen, first_blocks)
    probe_rendering(args.offscreen)
    out_dir = args.out or os.path.join(args.run_dir, "render")
    os.makedirs(out_dir, exist_ok=True)
    window, renderer = make_window(args.size, args.offscreen)
    place_camera(renderer, camera_points(series, first_blocks), args.view,
                 args.size[0] / float(args.size[1]))
    title = "%s  (%s)" % (os.path.basename(os.path.normpath(args.run_dir)), args.color)
    for time, number, vtm in chosen:
        blocks = read_frame(vtm)
        render_frame(window, renderer, blocks, time, args, style, title)
        write_png(window, os.path.join(out_dir, "frame_%06d.png" % number))
    if not args.quiet:
        print("wrote %d frame(s) to %s" % (len(chosen), out_dir))
        print("make a movie with:\n  " + movie_hint(out_dir, [e[1] for e in chosen]))


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        render_run(args)
    except RunError as e:
        sys.stderr.write("render_frames: error: %s\n" % e)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
