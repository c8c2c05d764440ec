"""Run inside the ParaView GUI (paraview --script=...) by solution_gui_screenshot.sh:
opens solve_elasticity.py's .pvtu (PTM_SOLUTION), warps it by Displacement,
clips it at the centre plane y = const, colours the cut body by von Mises
stress, adds the undeformed outline, and then writes the file PTM_READY, so
the shell script knows the GUI is ready to be captured (and then quits it).
The pipeline is built with paraview.simple in the GUI's own session, so it
appears in the Pipeline Browser like one made with the mouse."""
import os

from paraview.simple import (Clip, GetActiveCamera, GetActiveViewOrCreate, Hide, Hide3DWidgets, Outline, Render,
                             RenameSource, SetActiveSource, Show, WarpByVector, XMLPartitionedUnstructuredGridReader)
from solution_view import colour_by_von_mises  # Scripts/ is on PYTHONPATH (solution_gui_screenshot.sh)

solution = os.environ["PTM_SOLUTION"]
reader = XMLPartitionedUnstructuredGridReader(registrationName=os.path.basename(solution),
                                              FileName=[solution])
reader.CellArrayStatus = ["VonMises", "SubdomainId", "Rank", "GlobalCellIds"]
reader.PointArrayStatus = ["Displacement", "GlobalPointIds", "vtkGhostType"]
reader.UpdatePipeline()
bounds = reader.GetDataInformation().GetBounds()
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
centre = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
umax = reader.PointData["Displacement"].GetRange(-1)[1]
scale = float(os.environ.get("PTM_WARP_SCALE", 0)) or 0.15 * size / max(umax, 1e-300)

view = GetActiveViewOrCreate("RenderView")
warp = WarpByVector(registrationName="WarpByVector1", Input=reader,
                    Vectors=["POINTS", "Displacement"], ScaleFactor=scale)
clip = Clip(registrationName="Clip1", Input=warp, ClipType="Plane")
clip.ClipType.Origin = centre
clip.ClipType.Normal = [0, 1, 0]
clip.Invert = 0  # keep y > centre: the cut face looks at the camera
outline = Outline(registrationName="Outline1", Input=reader)
RenameSource("undeformed outline", outline)
Hide(reader, view)
Hide(warp, view)
display = Show(clip, view)
colour_by_von_mises(reader, display, view)
Show(outline, view)
view.OrientationAxesVisibility = 1
Render(view)  # paraview.simple resets the camera on a view's first render: have it now
view.CameraPosition = [bounds[1] + 2.2 * size, bounds[2] - 2.0 * size, bounds[5] + 1.0 * size]
view.CameraFocalPoint = centre
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
GetActiveCamera().Dolly(1.25)
SetActiveSource(clip)
Hide3DWidgets(proxy=clip.ClipType)  # the plane widget would hide half the body
Render(view)
print(f"solution_gui_screenshot: {solution}, displacement x {scale:.3g}, max |u| {umax:.4g}", flush=True)
with open(os.environ["PTM_READY"], "w") as f:
    f.write("ready\n")
