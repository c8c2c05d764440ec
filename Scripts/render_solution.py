"""Renders solve_elasticity.py's output in ParaView: the body warped by its
displacement and coloured by von Mises stress, with the undeformed outline.

  pvbatch --force-offscreen-rendering Scripts/render_solution.py out/ball_solution.pvtu OUT.png [SCALE]

(on a machine without a display put `xvfb-run -a` in front). SCALE multiplies
the displacement (default: the largest displacement becomes 15% of the body's size)."""
import os
import sys

from paraview.simple import (GetActiveViewOrCreate, Render, SaveScreenshot, Show, WarpByVector,
                             XMLPartitionedUnstructuredGridReader, Clip, Outline)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from solution_view import colour_by_von_mises  # noqa: E402

if len(sys.argv) < 3:
    sys.exit(__doc__)
solution, png = sys.argv[1], sys.argv[2]
reader = XMLPartitionedUnstructuredGridReader(FileName=[solution])
reader.UpdatePipeline()
info = reader.GetDataInformation()
bounds = info.GetBounds()
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
umax = reader.PointData["Displacement"].GetRange(-1)[1]
scale = float(sys.argv[3]) if len(sys.argv) > 3 else 0.15 * size / max(umax, 1e-300)
warp = WarpByVector(Input=reader, Vectors=["POINTS", "Displacement"], ScaleFactor=scale)
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1000, 800]
view.OrientationAxesVisibility = 1
# cut in half along y to show the stress inside, not only on the surface
clip = Clip(Input=warp, ClipType="Plane")
clip.ClipType.Origin = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
clip.ClipType.Normal = [0, 1, 0]
clip.Invert = 0  # keep y > centre: the cut face looks at the camera
display = Show(clip, view)
colour_by_von_mises(reader, display, view)
Show(Outline(Input=reader), view)
view.CameraPosition = [bounds[1] + 2.2 * size, bounds[2] - 2.0 * size, bounds[5] + 1.0 * size]
view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
view.CameraParallelProjection = 0
Render(view)
SaveScreenshot(png, view, ImageResolution=[1000, 800])
print(f"render: wrote {png} (displacement x {scale:.3g}, max |u| {umax:.4g})")
