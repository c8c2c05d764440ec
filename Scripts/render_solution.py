"""Renders solve_elasticity.py's output in ParaView: the body warped by its
displacement and coloured by von Mises stress, with the undeformed outline.

  pvbatch --force-offscreen-rendering Scripts/render_solution.py out/ball_solution.pvtu OUT.png [SCALE]

(on a machine without a display put `xvfb-run -a` in front). SCALE multiplies
the displacement (default: the largest displacement becomes 15% of the body's size)."""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Render,
                             SaveScreenshot, Show, WarpByVector, XMLPartitionedUnstructuredGridReader,
                             Clip, Outline, servermanager)
from vtk.numpy_interface import dataset_adapter as dsa
import numpy as np

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
ColorBy(display, ("CELLS", "VonMises"))
lut = GetColorTransferFunction("VonMises")
lut.ApplyPreset("Turbo", True)
# colour range to the 99th percentile: a few sliver or support-edge
# tetrahedra carry peaks that would otherwise leave the rest one colour
vm = dsa.WrapDataObject(servermanager.Fetch(reader)).CellData["VonMises"]
vm = np.concatenate([np.asarray(a) for a in vm.Arrays]) if hasattr(vm, "Arrays") else np.asarray(vm)
lut.RescaleTransferFunction(0.0, float(np.percentile(vm, 99)))
display.SetScalarBarVisibility(view, True)
Show(Outline(Input=reader), view)
view.CameraPosition = [bounds[1] + 2.2 * size, bounds[2] - 2.0 * size, bounds[5] + 1.0 * size]
view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
view.CameraParallelProjection = 0
Render(view)
SaveScreenshot(png, view, ImageResolution=[1000, 800])
print(f"render: wrote {png} (displacement x {scale:.3g}, max |u| {umax:.4g})")
