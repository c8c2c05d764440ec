"""Writes the two size sources of the SizeArray tests, both carrying the
point array h = 0.03*10^((z+1)/2) (the size of test_size_field.py, ten times
finer at the south pole of the unit ball than at the north):

* SURFACE.vtp: the input surface (e.g. Data/ball.off) with h on its points,
  made by ParaView's Calculator as a user would;
* GRID.vts: a background grid of 25^3 points over [-1.1, 1.1]^3 with h.

    pvpython --no-mpi make_size_sources.py PLUGIN INPUT SURFACE.vtp GRID.vts
"""
import os
import sys

from paraview import simple

if len(sys.argv) != 5:
    raise SystemExit(__doc__)
plugin, surface_in, surface_out, grid_out = sys.argv[1:]
for path in (surface_out, grid_out):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
simple.LoadPlugin(plugin, remote=False)
h = "0.03*10^((coordsZ+1)/2)"
surface = simple.Calculator(Input=simple.OpenDataFile(surface_in), ResultArrayName="h", Function=h)
simple.SaveData(surface_out, proxy=surface)
grid = simple.Transform(Input=simple.Wavelet(WholeExtent=[-12, 12, -12, 12, -12, 12]))
grid.Transform.Scale = [1.1 / 12] * 3
simple.SaveData(grid_out, proxy=simple.Calculator(Input=grid, ResultArrayName="h", Function=h))
for path in (surface_out, grid_out):
    if not os.path.isfile(path):
        raise SystemExit("make_size_sources.py: %s was not written" % path)
