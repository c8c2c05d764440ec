# trace generated using paraview version 5.11.0 (Tools > Start Trace in the
# GUI, then tidied: paths at the top, one comment per step).
#
# Meshes Data/bracket.stl with the four ParallelTetMesher filters, clips the
# tetrahedral mesh to show its inside, colours it by subdomain and saves a
# screenshot. Run it as
#
#   pvbatch Scripts/examples/mesh_in_paraview.py [OUT.png]              # 1 rank
#   mpiexec -n 2 pvbatch Scripts/examples/mesh_in_paraview.py [OUT.png] # 2 ranks
#
# (pvbatch renders through X: on a machine without a display put
# `xvfb-run -a -s "-screen 0 1280x1024x24"` in front), in pvpython, in the
# GUI's View > Python Shell (Run Script), or as `paraview --script=...`.
# The plugin is PTM_PLUGIN or the build tree's; the surface is PTM_SURFACE or
# Data/bracket.stl; OUT.png defaults to mesh_in_paraview.png.
import os
import sys

# ---- paths (a recorded trace has them written out; edit them here) --------
try:
    REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
except NameError:  # `paraview --script` and the Python shell may not set __file__
    REPOSITORY = os.environ.get("PTM_REPOSITORY", os.getcwd())
PLUGIN = os.environ.get("PTM_PLUGIN") or os.path.join(
    REPOSITORY, "build", "lib", "paraview-plugins", "ParallelTetMesher", "ParallelTetMesher.so")
SURFACE = os.environ.get("PTM_SURFACE") or os.path.join(REPOSITORY, "Data", "bracket.stl")
SCREENSHOT = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1].endswith(".png") else \
    os.environ.get("PTM_SCREENSHOT", "mesh_in_paraview.png")
SUBDOMAINS = int(os.environ.get("PTM_SUBDOMAINS", "4"))

# state file generated using paraview version 5.11.0
import paraview
paraview.compatibility.major = 5
paraview.compatibility.minor = 11

#### import the simple module from the paraview
from paraview.simple import *
#### disable automatic camera reset on 'Show'
paraview.simple._DisableFirstRenderCameraReset()

# Tools > Manage Plugins > Load New (on the server side when connected to a pvserver)
LoadPlugin(PLUGIN, remote=True, ns=globals())

# create a new 'STL Reader'
bracketstl = STLReader(registrationName='bracket.stl', FileNames=[SURFACE])

# Filters > Meshing > Volume Balanced Cutter
volumeBalancedCutter1 = VolumeBalancedCutter(registrationName='VolumeBalancedCutter1', Input=bracketstl)
volumeBalancedCutter1.NumberOfSubdomains = SUBDOMAINS
volumeBalancedCutter1.Strategy = 'RecursiveBisection'
volumeBalancedCutter1.Direction = 'Inertia'
volumeBalancedCutter1.BalanceCriterion = 'Volume'
volumeBalancedCutter1.BalanceTolerance = 0.01

# Filters > Meshing > Interface Triangulator
interfaceTriangulator1 = InterfaceTriangulator(registrationName='InterfaceTriangulator1', Input=volumeBalancedCutter1)
interfaceTriangulator1.MinimumAngle = 20.7
interfaceTriangulator1.MaximumEdgeLength = 0.0

# Filters > Meshing > Surface Relaxer
surfaceRelaxer1 = SurfaceRelaxer(registrationName='SurfaceRelaxer1', Input=interfaceTriangulator1)
surfaceRelaxer1.NumberOfIterations = 10
surfaceRelaxer1.RelaxationFactor = 0.5
surfaceRelaxer1.FeatureAngle = 30.0
surfaceRelaxer1.Region = 'NearCuts'

# Filters > Meshing > Parallel Tet Mesher
parallelTetMesher1 = ParallelTetMesher(registrationName='ParallelTetMesher1', Input=surfaceRelaxer1)
parallelTetMesher1.RadiusEdgeRatio = 2.0
parallelTetMesher1.MaximumVolume = 0.0
parallelTetMesher1.MinimumDihedralAngle = 0.0

# Filters > Common > Clip: whole tetrahedra (Crinkle clip) on the far side of
# the plane y = 1.5, through the rib, the boss and its hole
clip1 = Clip(registrationName='Clip1', Input=OutputPort(parallelTetMesher1, 0))
clip1.ClipType = 'Plane'
clip1.ClipType.Origin = [3.0, 1.5, 1.25]
clip1.ClipType.Normal = [0.0, -1.0, 0.0]
clip1.Crinkleclip = 1

# ----------------------------------------------------------------
# setup views used in the visualization
# ----------------------------------------------------------------

# get active view
renderView1 = GetActiveViewOrCreate('RenderView')
renderView1.OrientationAxesVisibility = 1
renderView1.Background = [1.0, 1.0, 1.0]
try:  # 5.11: a view's own background instead of the palette's
    renderView1.UseColorPaletteForBackground = 0
except AttributeError:
    pass

# the input surface as feature edges, for the half the clip removed
bracketstlDisplay = Show(bracketstl, renderView1, 'GeometryRepresentation')
bracketstlDisplay.Representation = 'Feature Edges'
bracketstlDisplay.AmbientColor = [0.3, 0.3, 0.3]
bracketstlDisplay.DiffuseColor = [0.3, 0.3, 0.3]

# show the clipped mesh with its edges, coloured by subdomain
clip1Display = Show(clip1, renderView1, 'UnstructuredGridRepresentation')
clip1Display.Representation = 'Surface With Edges'
clip1Display.EdgeColor = [0.15, 0.15, 0.2]
ColorBy(clip1Display, ('CELLS', 'SubdomainId'))

# subdomains are categories: one colour each, and a legend
subdomainIdLUT = GetColorTransferFunction('SubdomainId')
subdomainIdLUT.InterpretValuesAsCategories = 1
subdomainIdLUT.AnnotationsInitialized = 1
subdomainIdLUT.Annotations = sum([[str(s), 'subdomain %d' % s] for s in range(SUBDOMAINS)], [])
subdomainIdLUT.ApplyPreset('Brewer Qualitative Set2', True)
clip1Display.SetScalarBarVisibility(renderView1, True)
subdomainIdLUTColorBar = GetScalarBar(subdomainIdLUT, renderView1)
subdomainIdLUTColorBar.Title = 'SubdomainId'
subdomainIdLUTColorBar.TitleColor = [0.1, 0.1, 0.1]
subdomainIdLUTColorBar.LabelColor = [0.1, 0.1, 0.1]
subdomainIdLUTColorBar.TitleFontSize = 16
subdomainIdLUTColorBar.LabelFontSize = 14
subdomainIdLUTColorBar.WindowLocation = 'Upper Right Corner'

# camera: from the front left, above, looking at the cut face
renderView1.CameraPosition = [0.0, -4.4, 8.8]
renderView1.CameraFocalPoint = [3.0, 1.6, 0.8]
renderView1.CameraViewUp = [0.0, 0.0, 1.0]
renderView1.CameraParallelProjection = 1
renderView1.ResetCamera(False)
GetActiveCamera().Zoom(1.15)

# in the GUI: no clip-plane widget over the mesh, and the mesher's
# properties in the Properties panel
Hide3DWidgets(proxy=clip1.ClipType)
SetActiveSource(parallelTetMesher1)

# File > Save Screenshot
SaveScreenshot(SCREENSHOT, renderView1, ImageResolution=[1200, 800], FontScaling='Do not scale fonts')
print("mesh_in_paraview: %d tetrahedra in %d subdomains, %d shown after the clip; wrote %s" % (
    parallelTetMesher1.GetDataInformation(0).GetNumberOfCells(), SUBDOMAINS,
    clip1.GetDataInformation().GetNumberOfCells(), os.path.abspath(SCREENSHOT)))
