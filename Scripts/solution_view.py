"""What the two pictures of the elasticity solution share (render_solution.py,
run by pvbatch, and solution_gui_screenshot.py, run inside the GUI)."""
import numpy as np
from paraview.simple import ColorBy, GetColorTransferFunction, servermanager
from vtk.numpy_interface import dataset_adapter as dsa


def colour_by_von_mises(reader, display, view):
    """Colours `display` by the cell array VonMises (Turbo), the range up to
    the 99th percentile of `reader`'s values, with its colour bar."""
    ColorBy(display, ("CELLS", "VonMises"))
    lut = GetColorTransferFunction("VonMises")
    lut.ApplyPreset("Turbo", True)
    # colour range to the 99th percentile: a few sliver or support-edge
    # tetrahedra carry peaks that would otherwise leave the rest one colour
    vm = dsa.WrapDataObject(servermanager.Fetch(reader)).CellData["VonMises"]
    vm = np.concatenate([np.asarray(a) for a in vm.Arrays]) if hasattr(vm, "Arrays") else np.asarray(vm)
    lut.RescaleTransferFunction(0.0, float(np.percentile(vm, 99)))
    display.SetScalarBarVisibility(view, True)
