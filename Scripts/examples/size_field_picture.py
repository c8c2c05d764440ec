"""The README's size-field picture: the ball meshed with a size ten times
finer at its south pole than at its north pole, cut in half (whole
tetrahedra, so their sizes show), coloured by subdomain.

  mpiexec -n 2 pvbatch Scripts/tetmesh.py Data/ball.off -o out/graded/ball.pvtu --subdomains 4 \\
      --size 0.3 --size-expression "0.03*10^((z+1)/2)"
  pvbatch --force-offscreen-rendering Scripts/examples/size_field_picture.py out/graded/ball.pvtu OUT.png
"""
import sys

from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Render,
                             SaveScreenshot, Show, XMLPartitionedUnstructuredGridReader)

if len(sys.argv) != 3:
    sys.exit(__doc__)
reader = XMLPartitionedUnstructuredGridReader(FileName=[sys.argv[1]])
reader.UpdatePipeline()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [900, 900]
view.OrientationAxesVisibility = 1
clip = Clip(Input=reader, ClipType="Plane")
clip.ClipType.Origin = [0, 0, 0]
clip.ClipType.Normal = [0, 1, 0]
clip.Crinkleclip = 1  # whole tetrahedra
clip.Invert = 0  # keep y > 0: the cut face looks at the camera
display = Show(clip, view)
display.SetRepresentationType("Surface With Edges")
display.EdgeColor = [0.15, 0.15, 0.2]
ColorBy(display, ("CELLS", "SubdomainId"))
lut = GetColorTransferFunction("SubdomainId")
lut.ApplyPreset("Blue Orange (divergent)", True)
display.SetScalarBarVisibility(view, True)
view.CameraPosition = [0.6, -4.0, 0.3]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[900, 900])
print("size_field_picture: wrote " + sys.argv[2])
