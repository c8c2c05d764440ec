"""Scaling projection: how the pipeline would do on P ranks, from one rank.

For each K, the surface stages run once on one rank (subdomain_surfaces.py),
then every subdomain is meshed on its own with the project's TetGen call
(serial_tetgen, same switches and bound) and timed. With the plugin's own
rank assignment (assign_subdomains_to_ranks below, the rule of
Filters/Core/cut/SubdomainAssignment.cpp) the predicted wall time on P ranks is

    makespan(P) = surface stages(K) + max over ranks of the sum of its subdomains' seconds

because every rank computes the surface stages on the whole surface (README,
Limits) and then meshes its own subdomains one after another. The predicted
parallel efficiency against serial TetGen on the whole surface is

    efficiency(P) = T_serial / (P x makespan(P)).

What it leaves out, so it is an upper bound: numbering, assembly and writing
of the output, the gather and all-reduces over the network, and the memory
bandwidth shared by ranks on one node (two TetGen processes side by side on
this 2-core machine give about 1.4x the throughput of one, README "Measured").
"""
import json
import math
import os
import subprocess
import time

import peers


def assign_subdomains_to_ranks(measures, ranks):
    """ptm::assignSubdomainsToRanks: K <= P gives subdomain s to rank s; with
    over-decomposition longest first, each subdomain in order of decreasing
    measure (ties by number) going to the rank with the least so far (the
    lowest of equal ones)."""
    K = len(measures)
    if ranks <= 1:
        return [0] * K
    if K <= ranks:
        return list(range(K))
    cost = [m if math.isfinite(m) and m > 0 else 0.0 for m in measures]
    owner, load = [0] * K, [0.0] * ranks
    for s in sorted(range(K), key=lambda s: -cost[s]):  # sorted is stable: ties by number
        r = load.index(min(load))
        owner[s] = r
        load[r] += cost[s]
    return owner


def makespan(subdomain_seconds, measures, ranks):
    per_rank = [0.0] * ranks
    for s, r in enumerate(assign_subdomains_to_ranks(measures, ranks)):
        per_rank[r] += subdomain_seconds[s]
    return max(per_rank), per_rank


def project_one(case, K, folder, plugin, serial_tetgen, log):
    """Surface stages and per-subdomain meshing for one K; returns the record."""
    os.makedirs(folder, exist_ok=True)
    command = ["pvbatch", os.path.join(peers.HERE, "subdomain_surfaces.py"), case.stl, str(K), repr(case.size),
               plugin, folder]
    p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       env=peers.mpi_environment())
    log.write(p.stdout)
    if p.returncode != 0:
        reason = [l for l in p.stdout.splitlines() if l.startswith("subdomain_surfaces:")]
        raise peers.PeerFailed("the surface stages failed for K = %d: %s" % (
            K, reason[-1].split(": ", 1)[1] if reason else p.stdout[-2000:]))
    with open(os.path.join(folder, "surfaces.json")) as f:
        surfaces = json.load(f)
    seconds, tets = [], []
    for path in surfaces["files"]:
        out = subprocess.run([serial_tetgen, path, "2.0", repr(case.maximum_volume)], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        if out.returncode != 0:
            raise peers.PeerFailed("subdomain %d of %d cannot be meshed (%s): %s" % (
                len(seconds), K, path, out.stdout.strip().splitlines()[-1]))
        r = json.loads(out.stdout.strip().splitlines()[-1])
        seconds.append(r["seconds"])
        tets.append(r["tetrahedra"])
        os.remove(path)  # the subdomain surfaces of a 5 M case take a lot of space
    return {
        "subdomains": K,
        "surface_stage_seconds": surfaces["surface_stage_seconds"],
        "stage_seconds": surfaces["seconds"],
        "interface_area": surfaces["interface_area"],
        "boundary_area": surfaces["boundary_area"],
        "interface_triangles": surfaces["interface_triangles"],
        "subdomain_measure": surfaces["subdomain_measure"],
        "subdomain_seconds": seconds,
        "subdomain_tetrahedra": tets,
        "tetrahedra": sum(tets),
        "meshing_seconds_sum": sum(seconds),
    }


def predict(record, serial_seconds):
    """Makespan and efficiency for P = K and P = K/4 (over-decomposition)."""
    K = record["subdomains"]
    predictions = {}
    for label, P in (("P=K", K), ("P=K/4", max(1, K // 4))):
        longest, per_rank = makespan(record["subdomain_seconds"], record["subdomain_measure"], P)
        total = record["surface_stage_seconds"] + longest
        predictions[label] = {
            "ranks": P,
            "meshing_makespan_seconds": longest,
            "makespan_seconds": total,
            "efficiency": serial_seconds / (P * total),
            "efficiency_meshing_only": serial_seconds / (P * longest),
            "balance_max_over_mean": longest / (sum(per_rank) / P),
        }
    return predictions


def run_projection(case, Ks, folder, plugin, serial_tetgen, serial_seconds, say):
    records = []
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "projection.log"), "w") as log:
        for K in Ks:
            start = time.perf_counter()
            try:
                record = project_one(case, K, os.path.join(folder, "K%d" % K), plugin, serial_tetgen, log)
            except peers.PeerFailed as e:
                # a K the pipeline cannot do is a finding, not the end of the run
                records.append({"subdomains": K, "error": str(e)})
                say("  projection K=%d FAILED: %s" % (K, str(e).replace("\n", " ")))
                continue
            record["predictions"] = predict(record, serial_seconds)
            records.append(record)
            say("  projection K=%d: %d tets, surface stages %.2f s, subdomains %.1f s in all, "
                "efficiency %.0f%% at P=K, %.0f%% at P=K/4 (%.0f s)" % (
                    K, record["tetrahedra"], record["surface_stage_seconds"], record["meshing_seconds_sum"],
                    100 * record["predictions"]["P=K"]["efficiency"],
                    100 * record["predictions"]["P=K/4"]["efficiency"], time.perf_counter() - start))
    return records
