"""The picture of README's "CAD input and wrapping dirty surfaces".

    pvbatch --force-offscreen-rendering Scripts/examples/cad_and_wrap_picture.py OUTPUTS OUT.png

OUTPUTS is the folder the cad_and_wrap tests write
(build/Testing/Python/output/cad_and_wrap): left, the boundary of the
hammer.iges mesh coloured by CADFaceId; right, the boundary of the wrapped
coarse bottle (the OCCT sample whose thread self-intersects) coloured by
subdomain, with the dirty input as black wire.
"""
import os
import sys

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))


def main(outputs, image):
    plugin = os.environ.get("PTM_PLUGIN") or os.path.join(
        HERE, "..", "..", "build", "lib", "paraview-plugins", "ParallelTetMesher", "ParallelTetMesher.so")
    simple.LoadPlugin(plugin, remote=False)
    layout = simple.CreateLayout("cad and wrap")
    left = simple.CreateView("RenderView")
    right = simple.CreateView("RenderView")
    simple.AssignViewToLayout(view=left, layout=layout, hint=0)
    simple.AssignViewToLayout(view=right, layout=layout, hint=0)

    hammer = simple.XMLPartitionedPolydataReader(FileName=os.path.join(outputs, "iges_boundary.pvtp"))
    shown = simple.Show(hammer, left)
    simple.ColorBy(shown, ("CELLS", "CADFaceId"))
    lut = simple.GetColorTransferFunction("CADFaceId")
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.AutomaticRescaleRangeMode = "Never"  # the bottle's own CADFaceId must not widen it
    lut.RescaleTransferFunction(0, 44)
    shown.SetScalarBarVisibility(left, True)
    bar = simple.GetScalarBar(lut, left)
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.Title = "CADFaceId"
    bar.ComponentTitle = ""
    left.CameraPosition = [1, -1.2, 0.8]
    left.CameraFocalPoint = [0, 0, 0]
    left.CameraViewUp = [0, 0, 1]
    left.ResetCamera()

    wrapped = simple.XMLPartitionedPolydataReader(
        FileName=os.path.join(outputs, "wrap-self-intersecting_boundary.pvtp"))
    shown = simple.Show(wrapped, right)
    simple.ColorBy(shown, ("CELLS", "SubdomainId"))
    shown.Opacity = 0.55
    simple.GetColorTransferFunction("SubdomainId").ApplyPreset("Cool to Warm", True)
    dirty = simple.CADSurfaceReader(FileName="/usr/share/opencascade/data/occ/bottle.brep",
                                    RelativeLinearDeflection=0.005)
    wire = simple.Show(dirty, right)
    wire.SetRepresentationType("Wireframe")
    wire.AmbientColor = wire.DiffuseColor = [0, 0, 0]
    simple.ColorBy(wire, None)
    # the neck, where the thread crosses itself and the wrap rounds it
    right.CameraPosition = [60, -90, 110]
    right.CameraFocalPoint = [0, 0, 62]
    right.CameraViewUp = [0, 0, 1]
    right.CameraViewAngle = 30
    for view in (left, right):
        view.OrientationAxesVisibility = 0
        view.Background = [1, 1, 1]
        try:
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
    simple.SaveScreenshot(image, layout, ImageResolution=[1600, 700])


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
