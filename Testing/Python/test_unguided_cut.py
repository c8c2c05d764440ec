"""A cut whose volume measure gives no guide, through the cutter alone.

    pvbatch test_unguided_cut.py PLUGIN DATA_DIR RANKS

OpenFOAM's bullet (openfoam-examples, resources/geometry/bullet.stl.gz, GPL-3+;
Data/regression/openfoam_bullet.off) cut into 40 subdomains by recursive
bisection with the batch command's defaults (cost balance, thickness cap,
size 0.000492433): the measure function of one part along its 33rd cut's
normal totals -1.4e-8 for a part of +2.2e-8, so the plane it gave lay outside
the part, and until session 29 the cut failed on every rank, saying the
subdomains were too many for the surface (K = 32 and K = 40 by volume cut
it). Checks: the cut succeeds with 40 subdomains, and their volumes add up to
the input's.
"""
import sys

import ptm_testing as t
from paraview import simple

INPUT_VOLUME = 1.4048254184384606e-06


def check(plugin, data, ranks):
    simple.LoadPlugin(plugin, remote=False)
    reader = simple.OpenDataFile(data + "/regression/openfoam_bullet.off")
    cut = simple.VolumeBalancedCutter(
        Input=reader, NumberOfSubdomains=40, Strategy="RecursiveBisection", Direction="Inertia",
        BalanceCriterion="PredictedCost", MaximumSize=0.000492433, RemoveFlatCrossings=1, SizeByThickness=1)
    cut.UpdatePipeline()
    fd = cut.GetClientSideObject().GetOutputDataObject(0).GetFieldData()
    failures = []
    count, volumes = fd.GetArray("NumberOfSubdomains"), fd.GetArray("SubdomainVolume")
    if count is None or volumes is None:
        failures.append("the cut gave no subdomains (it failed)")
    else:
        total = sum(volumes.GetValue(i) for i in range(volumes.GetNumberOfTuples()))
        print("unguided cut on %s ranks: %d subdomains, volume %.17g" % (ranks, count.GetValue(0), total))
        if count.GetValue(0) != 40:
            failures.append("%d subdomains, not 40" % count.GetValue(0))
        if not abs(total - INPUT_VOLUME) <= 1e-9 * INPUT_VOLUME:
            failures.append("the subdomains' volumes add up to %.17g, not %.17g" % (total, INPUT_VOLUME))
    if failures:
        raise AssertionError("; ".join(failures))


t.run_checks(lambda: check(*sys.argv[1:4]))
