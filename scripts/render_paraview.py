"""Renders a wirepack run file with ParaView, in the paper's style (issue 18).

The wire is a tube of the wire's radius (half of it with --half-radius, which shows the
inside of the packing) coloured by its dimensionless curvature kappa R on ParaView's "Turbo"
rainbow map over [0, 3] by default (--kappa-range): dark blue is straight (0), a coil lying on
the wall (kappa R = 1) is cyan to green, yellow 2, red 3 and beyond. An elastic shell is drawn
translucent and coloured by a field (--shell-field):
  area_stretch      current / rest area per face, on "Cool to Warm" (blue-white-red),
                    white at 1, symmetric about 1 out to the 99th percentile of |stretch - 1|
                    over the whole run (default);
  contact_pressure  the wire's contact force per vertex over the vertex's area [Pa],
                    on "Inferno (matplotlib)" from 0 to the run's 99th percentile;
  clamped           the clamped rim (1) and the free shell (0);
  none              plain grey.
Run files from before the fields (no /snapshots/K/shell_area_stretch) get the area stretch
from snapshot 0, the shell at rest; they have no contact pressure (drawn grey). A rigid
sphere is drawn as a translucent grey sphere of radius R.

Run under ParaView's batch interpreter, off-screen (xvfb-run where there is no display):
  xvfb-run -a pvbatch scripts/render_paraview.py RUN.h5 [--out PICTURE.png] [--snapshot K]
      [--movie MOVIE.mp4] [--half-radius] [--shell-field F] [--size WxH] [--kappa-range A,B]
      [--fps N] [--title TEXT]
`wirepack render` validates the arguments, then runs this. Needs h5py (python3-h5py) and,
for --movie, ffmpeg. Every output is written to a temporary name and renamed. Exit codes:
0 done, 2 bad input (nothing written), 1 a rendering or encoding failure.
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile


def fail(msg, code=2):
    sys.stderr.write("render_paraview: %s\n" % msg)
    sys.exit(code)


def parse_args(argv):
    p = argparse.ArgumentParser(prog="render_paraview.py", description=__doc__.split("\n")[0])
    p.add_argument("run", help="run file (HDF5)")
    p.add_argument("--out", default="", help="picture to write (PNG)")
    p.add_argument("--snapshot", type=int, default=-1, help="snapshot index (default: the last)")
    p.add_argument("--movie", default="", help="movie over all snapshots to write (MP4, H.264)")
    p.add_argument("--half-radius", action="store_true", help="draw the wire at half its radius")
    p.add_argument("--shell-field", default="area_stretch",
                   choices=["area_stretch", "contact_pressure", "clamped", "none"])
    p.add_argument("--size", default="1200x900", help="picture size WxH in pixels")
    p.add_argument("--kappa-range", default="0,3", help="kappa R at the ends of the colour map")
    p.add_argument("--fps", type=float, default=4.0, help="movie frames per second")
    p.add_argument("--title", default=None, help="title (default: the run file's name)")
    a = p.parse_args(argv)
    if not a.out and not a.movie:
        fail("nothing to write: give --out PICTURE.png and/or --movie MOVIE.mp4")
    try:
        w, h = (int(v) for v in a.size.lower().split("x"))
        assert 16 <= w <= 8192 and 16 <= h <= 8192
        a.size = (w, h)
    except Exception:
        fail("--size: must be WxH with 16 <= W, H <= 8192 (got %r)" % a.size)
    try:
        lo, hi = (float(v) for v in a.kappa_range.split(","))
        assert lo < hi
        a.kappa_range = (lo, hi)
    except Exception:
        fail("--kappa-range: must be A,B with A < B (got %r)" % a.kappa_range)
    return a


# ---- the run file ----

class Run:
    """A run file's geometry and fields, read with h5py (layouts 1 and 2)."""

    def __init__(self, path):
        import h5py

        if not os.path.isfile(path):
            fail("%s: no such run file" % path)
        try:
            self.f = h5py.File(path, "r")
        except OSError as e:
            fail("%s: not an HDF5 run file (%s)" % (path, e))
        if "config" not in self.f.attrs or "snapshots" not in self.f:
            fail("%s: not a wirepack run file (no config attribute or /snapshots)" % path)
        self.config = json.loads(self.f.attrs["config"])
        # Resolved scenes have every key; hand-made files may not: the scene defaults then.
        self.r = float(self.config.get("wire", {}).get("radius", 0.5e-3))  # wire radius [m]
        self.R = float(self.config.get("rho", 20.0)) * self.r  # sphere radius [m]
        self.elastic = self.config.get("shell") == "elastic"
        self.keys = sorted(self.f["snapshots"].keys(), key=int)
        if not self.keys:
            fail("%s: the run file has no snapshots" % path)
        self._rest_areas = None

    def __len__(self):
        return len(self.keys)

    def snapshot(self, k):
        """Wire (n x 3) [m], kappa R (n), l, and the shell (vertices, triangles, fields) or None."""
        import numpy as np

        g = self.f["snapshots"][self.keys[k]]
        wire = np.asarray(g["wire"], dtype=float).reshape(-1, 3)
        curv = np.asarray(g["curvature"], dtype=float) if "curvature" in g else np.zeros(len(wire))
        l = float(g.attrs["l"])
        shell = None
        if "shell_vertices" in g and len(g["shell_vertices"]) > 0:
            tris = g["shell_triangles"] if "shell_triangles" in g else self.f["shell_triangles"]
            shell = {"x": np.asarray(g["shell_vertices"], dtype=float).reshape(-1, 3),
                     "t": np.asarray(tris, dtype=np.int64).reshape(-1, 3)}
            shell["area_stretch"] = (np.asarray(g["shell_area_stretch"], dtype=float)
                                     if "shell_area_stretch" in g else self.stretch_from_rest(shell))
            if "shell_contact_force" in g:
                F = np.linalg.norm(np.asarray(g["shell_contact_force"], dtype=float), axis=1)
                shell["contact_pressure"] = F / np.maximum(vertex_areas(shell), 1e-300)
            if "shell_clamped" in g:
                shell["clamped"] = np.asarray(g["shell_clamped"], dtype=float)
            elif "shell_clamped" in self.f:
                shell["clamped"] = np.asarray(self.f["shell_clamped"], dtype=float)
        return wire, curv * self.R, l, shell

    def stretch_from_rest(self, shell):
        """Area stretch against snapshot 0 (l = 0: the shell at rest), for older run files."""
        if self._rest_areas is None:
            g = self.f["snapshots"][self.keys[0]]
            rest = {"x": g["shell_vertices"][()].reshape(-1, 3), "t": shell["t"]}
            self._rest_areas = face_areas(rest)
        return face_areas(shell) / self._rest_areas


def face_areas(shell):
    import numpy as np

    x, t = shell["x"], shell["t"]
    a, b, c = x[t[:, 0]], x[t[:, 1]], x[t[:, 2]]
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def vertex_areas(shell):
    import numpy as np

    A = np.zeros(len(shell["x"]))
    third = face_areas(shell) / 3.0
    for c in range(3):
        np.add.at(A, shell["t"][:, c], third)
    return A


# ---- VTK data ----

def wire_polydata(wire, kappa_R):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkPolyLine

    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(wire.copy(), deep=True))
    pd.SetPoints(pts)
    line = vtkPolyLine()
    line.GetPointIds().SetNumberOfIds(len(wire))
    for i in range(len(wire)):
        line.GetPointIds().SetId(i, i)
    cells = vtkCellArray()
    cells.InsertNextCell(line)
    pd.SetLines(cells)
    arr = numpy_to_vtk(kappa_R.copy(), deep=True)
    arr.SetName("kappa_R")
    pd.GetPointData().AddArray(arr)
    return pd


def shell_polydata(shell):
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(shell["x"].copy(), deep=True))
    pd.SetPoints(pts)
    t = shell["t"]
    conn = np.hstack([np.full((len(t), 1), 3, dtype=np.int64), t]).ravel()
    cells = vtkCellArray()
    cells.SetCells(len(t), numpy_to_vtkIdTypeArray(conn, deep=True))
    pd.SetPolys(cells)
    arr = numpy_to_vtk(shell["area_stretch"].copy(), deep=True)
    arr.SetName("area_stretch")
    pd.GetCellData().AddArray(arr)
    for name in ("contact_pressure", "clamped"):
        if name in shell:
            a = numpy_to_vtk(shell[name].copy(), deep=True)
            a.SetName(name)
            pd.GetPointData().AddArray(a)
    return pd


# ---- the scene ----

class Scene:
    """One ParaView view whose wire and shell are replaced for every snapshot."""

    def __init__(self, run, args, shell_range):
        import paraview.simple as pv

        self.pv, self.run, self.args = pv, run, args
        w, h = args.size
        self.scale = framing(run, w / h)  # the camera's distance over the default one
        self.view = pv.CreateView("RenderView")
        self.view.ViewSize = [w, h]
        self.view.OrientationAxesVisibility = 0
        self.view.Background = [1.0, 1.0, 1.0]
        try:  # ParaView >= 5.10: the background is a palette setting unless told otherwise
            self.view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        pv.SetActiveView(self.view)

        # Wire: a tube coloured by kappa R.
        self.wire_src = pv.PVTrivialProducer()
        self.tube = None  # made once the producer has data (a filter checks its input's type)
        self.wire_rep = None
        self.kappa_lut = pv.GetColorTransferFunction("kappa_R")
        self.kappa_lut.ApplyPreset("Turbo", True)
        self.kappa_lut.RescaleTransferFunction(*args.kappa_range)
        self.kappa_lut.AutomaticRescaleRangeMode = "Never"

        # Shell: translucent, coloured by a field; a rigid sphere: translucent grey.
        self.shell_src = None
        self.shell_rep = None
        self.field = args.shell_field
        if run.elastic:
            self.shell_src = pv.PVTrivialProducer()
            self.shell_lut = None
            if self.field != "none":
                self.shell_lut = pv.GetColorTransferFunction(self.field)
                preset = {"area_stretch": "Cool to Warm", "contact_pressure": "Inferno (matplotlib)",
                          "clamped": "Cool to Warm"}[self.field]
                self.shell_lut.ApplyPreset(preset, True)
                self.shell_lut.RescaleTransferFunction(*shell_range)
                self.shell_range = shell_range
                self.shell_lut.AutomaticRescaleRangeMode = "Never"
        else:
            sphere = pv.Sphere(Radius=run.R, ThetaResolution=64, PhiResolution=48)
            rep = pv.Show(sphere, self.view)
            rep.ColorArrayName = ["POINTS", ""]  # solid colour
            rep.DiffuseColor = [0.6, 0.6, 0.6]
            rep.AmbientColor = [0.6, 0.6, 0.6]
            rep.Opacity = 0.12

        self.text = pv.Text()
        text_rep = pv.Show(self.text, self.view)
        text_rep.WindowLocation = "Upper Center"
        text_rep.FontSize = 14
        text_rep.Color = [0.1, 0.1, 0.1]

    def camera(self):
        """Side view with the hole at the bottom, the whole sphere in the picture, farther where
        the packing reaches beyond it (framing; set after every Show: the first one resets the
        camera)."""
        d = self.run.R * self.scale
        self.view.CameraFocalPoint = [0.0, 0.0, 0.0]
        self.view.CameraPosition = [c * d for c in CAMERA_POSITION]
        self.view.CameraViewUp = [0.0, 0.0, 1.0]
        self.view.CameraViewAngle = VIEW_ANGLE

    def show(self, k):
        pv, run, args = self.pv, self.run, self.args
        wire, kappa_R, l, shell = run.snapshot(k)
        title = args.title if args.title is not None else os.path.basename(args.run)
        self.text.Text = "%s    l = %.2f" % (title, l)

        if len(wire) >= 2:
            self.wire_src.GetClientSideObject().SetOutput(wire_polydata(wire, kappa_R))
            self.wire_src.MarkModified(self.wire_src)
            if self.wire_rep is None:
                self.tube = pv.Tube(Input=self.wire_src)
                self.tube.Radius = run.r * (0.5 if args.half_radius else 1.0)
                self.tube.NumberofSides = 20
                self.tube.Capping = 1
                self.wire_rep = pv.Show(self.tube, self.view)
                pv.ColorBy(self.wire_rep, ("POINTS", "kappa_R"))
                self.wire_rep.LookupTable = self.kappa_lut
                self.kappa_lut.RescaleTransferFunction(*args.kappa_range)  # ColorBy rescaled it
                self.wire_rep.Specular = 0.3
                bar = pv.GetScalarBar(self.kappa_lut, self.view)
                bar.Title = "kappa R"
                bar.ComponentTitle = ""
                bar.WindowLocation = "Any Location"
                bar.Position = list(BAR_RIGHT)
                bar.ScalarBarLength = 0.5
                bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
                bar.RangeLabelFormat = "%.3g"
                bar.Visibility = 1
            self.wire_rep.Visibility = 1
        elif self.wire_rep is not None:
            self.wire_rep.Visibility = 0

        if self.shell_src is not None and shell is not None:
            pd = shell_polydata(shell)
            self.shell_src.GetClientSideObject().SetOutput(pd)
            self.shell_src.MarkModified(self.shell_src)
            if self.shell_rep is None:
                self.shell_rep = pv.Show(self.shell_src, self.view)
                self.shell_rep.Opacity = 0.3
                has_field = self.shell_lut is not None and (
                    pd.GetCellData().HasArray(self.field) or pd.GetPointData().HasArray(self.field))
                if has_field:
                    assoc = "CELLS" if self.field == "area_stretch" else "POINTS"
                    pv.ColorBy(self.shell_rep, (assoc, self.field))
                    self.shell_rep.LookupTable = self.shell_lut
                    self.shell_lut.RescaleTransferFunction(*self.shell_range)
                    bar = pv.GetScalarBar(self.shell_lut, self.view)
                    bar.Title = {"area_stretch": "area stretch", "contact_pressure": "p [Pa]",
                                 "clamped": "clamped"}[self.field]
                    bar.ComponentTitle = ""
                    bar.WindowLocation = "Any Location"
                    bar.Position = list(BAR_LEFT)
                    bar.ScalarBarLength = 0.5
                    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
                    bar.RangeLabelFormat = "%.3g"
                    bar.Visibility = 1
                else:
                    self.shell_rep.ColorArrayName = ["POINTS", ""]  # solid colour
                    self.shell_rep.DiffuseColor = [0.6, 0.6, 0.6]
        pv.Render(self.view)  # paraview.simple resets the camera at a view's first render
        self.camera()
        pv.Render(self.view)

    def save(self, path):
        self.pv.SaveScreenshot(path, self.view, ImageResolution=list(self.args.size),
                               TransparentBackground=0)


# The camera: side view from -y, a little above the equator, the sphere's centre in the middle
# (position in units of R, vertical view angle in degrees).
CAMERA_POSITION = (0.0, -3.9, 1.0)
VIEW_ANGLE = 30.0
# The colour bars (lower-left corners as fractions of the picture's width and height; each bar
# with its labels and title is ~0.08 wide) and the band of the picture between them that the
# packing may fill: x in [0.12, 0.88], i.e. 0.76 of the half-width about the centre.
BAR_LEFT = (0.03, 0.25)   # the shell's field
BAR_RIGHT = (0.89, 0.25)  # kappa R
SIDE_MARGIN = 0.76


def camera_axes():
    """Unit vectors of the default camera: forward (towards the sphere's centre), up, right."""
    import numpy as np

    forward = -np.asarray(CAMERA_POSITION) / np.linalg.norm(CAMERA_POSITION)
    up = np.array([0.0, 0.0, 1.0]) - forward[2] * forward
    up /= np.linalg.norm(up)
    return forward, up, np.cross(forward, up)


def fits(points, scale, R, aspect, margin=0.97, side=None):
    """Whether every point (n x 3) [m] lies inside `margin` of the picture's half-height and
    `side` of its half-width (default: the band between the colour bars, SIDE_MARGIN), seen by
    the perspective camera at `scale` times its distance."""
    import numpy as np

    side = SIDE_MARGIN if side is None else side
    forward, up, right = camera_axes()
    v = np.asarray(points, dtype=float) - scale * R * np.asarray(CAMERA_POSITION)
    depth = v @ forward
    if np.any(depth <= 0):
        return False
    t = np.tan(np.radians(VIEW_ANGLE / 2))
    return bool(np.all(np.abs(v @ up) <= margin * t * depth) and
                np.all(np.abs(v @ right) <= side * aspect * t * depth))


def framing(run, aspect, margin=0.97, side=None):
    """The camera's distance as a multiple of the default one (>= 1): the smallest (to 0.1 %) at
    which every snapshot's wire and shell lie inside `margin` of the picture's height and between
    its colour bars (fits), so that one run's
    pictures and movie share one framing. Moving the camera back along its axis leaves a point's
    offsets across the view unchanged and adds to its depth, so each point's condition
    |offset| <= t depth is linear in the distance: the scale is a maximum over the points. 1
    where the packing stays inside the sphere's view; a soft thin shell drawn out by the wire
    (twice R and more) needs up to ~2.2."""
    import numpy as np

    pts = []
    for k in range(len(run)):
        wire, _, _, shell = run.snapshot(k)
        pts.append(np.asarray(wire, dtype=float).reshape(-1, 3))
        if shell is not None:
            pts.append(shell["x"])
    p = np.vstack(pts)
    side = SIDE_MARGIN if side is None else side
    forward, up, right = camera_axes()
    t = np.tan(np.radians(VIEW_ANGLE / 2))
    # depth = p . forward + scale * |C|, with C the default camera position [m].
    need = np.maximum(np.abs(p @ up) / (margin * t),
                      np.abs(p @ right) / (side * aspect * t)) - p @ forward
    scale = float(np.max(need)) / (run.R * np.linalg.norm(CAMERA_POSITION))
    # Rounded up to 0.1 %: the points at the limit stay inside it whatever the rounding.
    return max(1.0, math.ceil(scale * 1000.0) / 1000.0)


def shell_range(run, field):
    """Colour range of the shell field over the whole run (a movie keeps one scale)."""
    import numpy as np

    if field == "clamped":
        return (0.0, 1.0)
    values = []
    for k in range(len(run)):
        _, _, _, shell = run.snapshot(k)
        if shell is not None and field in shell:
            values.append(shell[field])
    if not values:
        return (0.0, 1.0)
    v = np.concatenate(values)
    # The 99th percentile, not the largest: a few faces at the clamped rim stretch far more
    # than the rest of the shell and would wash out its colours (beyond: the end colours).
    if field == "area_stretch":
        d = max(float(np.percentile(np.abs(v - 1.0), 99)), 0.01)
        return (1.0 - d, 1.0 + d)
    hi = float(np.percentile(v[v > 0], 99)) if np.any(v > 0) else 0.0
    return (0.0, hi if hi > 0 else 1.0)


def main(argv):
    args = parse_args(argv)
    run = Run(args.run)
    n = len(run)
    k = args.snapshot if args.snapshot >= 0 else n - 1
    if k >= n:
        fail("--snapshot %d: the run file has %d snapshots (0 to %d)" % (args.snapshot, n, n - 1))
    if args.movie and not shutil.which("ffmpeg"):
        fail("--movie needs ffmpeg (scripts/install_paraview.sh installs it)")
    srange = shell_range(run, args.shell_field) if run.elastic else (0.0, 1.0)
    scene = Scene(run, args, srange)

    if args.out:
        tmp = args.out + ".tmp.png"
        scene.show(k)
        scene.save(tmp)
        os.replace(tmp, args.out)
        print(args.out)

    if args.movie:
        frames = tempfile.mkdtemp(prefix="wirepack-frames-")
        try:
            for i in range(n):
                scene.show(i)
                scene.save(os.path.join(frames, "frame_%05d.png" % i))
            tmp = args.movie + ".tmp.mp4"
            cmd = ["ffmpeg", "-y", "-loglevel", "error", "-framerate", str(args.fps),
                   "-i", os.path.join(frames, "frame_%05d.png"),
                   "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264",
                   "-pix_fmt", "yuv420p", "-r", str(args.fps), tmp]
            if subprocess.call(cmd) != 0:
                if os.path.exists(tmp):
                    os.remove(tmp)
                fail("ffmpeg failed to encode %s" % args.movie, 1)
            os.replace(tmp, args.movie)
        finally:
            shutil.rmtree(frames, ignore_errors=True)
        print(args.movie)
    return 0


if __name__ == "__main__":
    code = main(sys.argv[1:])
    sys.stdout.flush()
    sys.stderr.flush()
    # pvbatch 5.11 may crash while tearing down its proxies after the work is done; the
    # outputs are complete and renamed by now, so leave without the teardown.
    os._exit(code)
