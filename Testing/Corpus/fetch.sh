#!/usr/bin/env bash
# Build the corpus of real closed surfaces (issue #18): every file comes from a
# Debian package and was modelled by someone outside this project; CAD models
# are tessellated by their own tool (OpenSCAD, OpenCASCADE's incmesh, Gmsh).
#
#   bash Testing/Corpus/fetch.sh [OUT_DIR]            # default out/corpus
#   bash Testing/Corpus/fetch.sh --unseen [OUT_DIR]   # default out/unseen
#   bash Testing/Corpus/fetch.sh --fresh [OUT_DIR]    # default out/fresh
#
# --unseen builds a second set, for robustness runs (two of its surfaces,
# netgen's part1 and Prusa's cylinder, became regression files in
# Data/regression after failures found on them): surfaces from
# packages the main corpus does not touch (netgen-doc, prusa-slicer, cura,
# freecad-common, openscad-testing-data, openscad-mcad). Those packages are
# downloaded with apt-get download and unpacked under OUT_DIR/.work, not
# installed.
#
# --fresh builds a third such set: larger CGAL meshes (libcgal-demo) and STEP
# models of kicad-packages3d and calculix-cgx-examples, tessellated by the
# plugin's CAD reader code (CADTessellation.cpp, compiled here against
# Debian's OCCT, with the reader's defaults) as the sweeps read them.
#
# Writes OUT_DIR/NAME.off for every surface that is closed, edge- and
# vertex-manifold, consistently oriented, encloses a positive volume and does
# not intersect itself (CGAL exact check, check_surface.cpp), OUT_DIR/dirty/
# for the others, and OUT_DIR/corpus.tsv with one row per candidate (status,
# reason, sizes, origin). Deterministic: the same packages give the same bytes
# (single-threaded tessellators, fixed parameters, sorted lists).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SET=main
case "${1:-}" in --unseen | --fresh) SET="${1#--}"; shift ;; esac
DEFAULT_OUT=out/corpus
[ "$SET" != main ] && DEFAULT_OUT="out/$SET"
OUT="${1:-$DEFAULT_OUT}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
WORK="$OUT/.work"
rm -rf "$WORK/raw" "$OUT/dirty" "$OUT"/*.off
mkdir -p "$WORK/raw" "$WORK/lib" "$OUT/dirty"

PACKAGES="openscad occt-draw occt-misc libcgal-demo libcgal-dev gmsh gmsh-doc g++ libgmp-dev libmpfr-dev python3-numpy unzip"
[ "$SET" = fresh ] && PACKAGES="$PACKAGES libocct-data-exchange-dev libocct-modeling-algorithms-dev"
missing=""
for p in $PACKAGES; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
    echo "fetch: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
PY=/usr/bin/python3
TOOL="$HERE/surface_tool.py"

# the checker, independent of the plugin
g++ -O2 -std=c++17 -o "$WORK/check_surface" "$HERE/check_surface.cpp" -lgmp -lmpfr

# occt-draw loads its plugins as libTK*.so, which only the -dev packages
# provide: link them to the runtime libraries in a private directory
for f in /usr/lib/x86_64-linux-gnu/libTK*.so.7; do ln -sf "$f" "$WORK/lib/$(basename "$f" .7)"; done

CGAL_DATA=/usr/share/doc/libcgal-dev/data.tar.gz
OCC=/usr/share/opencascade/data
GD=/usr/share/doc/gmsh-doc
OSCAD=/usr/share/openscad/examples

# name | kind | source | note
# kinds: cgal (an OFF of CGAL's test data, as is), scad (openscad -o),
# occt (DRAWEXE: restore/igesbrep/testreadstep, incmesh with a deflection of
# 1/200 of the bounding box diagonal and 20 degrees, writestl), gmsh (gmsh -2,
# 1 thread, its default sizes, STL), stl (a bundled STL, as is)
CANDIDATES="
3torus|cgal|data/meshes/3torus.off|coarse genus-3 torus
double-torus-example|cgal|data/meshes/double-torus-example.off|genus-2 torus
eight|cgal|data/meshes/eight.off|figure eight (genus 2)
anchor|cgal|data/meshes/anchor.off|CAD anchor
fandisk|cgal|data/meshes/fandisk.off|CAD fan disk
joint|cgal|data/meshes/joint.off|CAD joint
couplingdown|cgal|data/meshes/couplingdown.off|CAD coupling
blade|cgal|data/meshes/blade.off|scanned turbine blade
elephant|cgal|data/meshes/elephant.off|organic
knot1|cgal|data/meshes/knot1.off|trefoil knot
rotor|cgal|data/meshes/rotor.off|CAD rotor
pinion|cgal|data/meshes/pinion.off|CAD pinion gear
spool|cgal|data/meshes/spool.off|CAD spool
mech-holes-shark|cgal|data/meshes/mech-holes-shark.off|CAD part with holes
femur|cgal|data/meshes/femur.off|scanned bone
mushroom|cgal|data/meshes/mushroom.off|organic
cow|cgal|data/meshes/cow.off|organic
handle|cgal|data/meshes/handle.off|handle (genus 1)
elk|cgal|data/meshes/elk.off|genus-1 sculpture
head|cgal|data/meshes/head.off|scanned head
dragknob|cgal|data/meshes/dragknob.off|CAD knob
part|cgal|data/meshes/part.off|CAD part
cactus|cgal|data/meshes/cactus.off|organic
bones|cgal|data/meshes/bones.off|scanned bones
turbine|cgal|data/meshes/turbine.off|CAD turbine
cheese|cgal|data/meshes/cheese.off|block with many holes
hand|cgal|data/meshes/hand.off|scanned hand
oblong|cgal|data/meshes/oblong.off|oblong blob
triceratops|cgal|data/meshes/triceratops.off|organic
cylinder|cgal|data/meshes/cylinder.off|long-triangle cylinder
scad-example001|scad|$OSCAD/Old/example001.scad|sphere minus three cylinders
scad-example002|scad|$OSCAD/Old/example002.scad|CSG block
scad-example003|scad|$OSCAD/Old/example003.scad|CSG cross
scad-example005|scad|$OSCAD/Old/example005.scad|cylinders and cone
scad-example024|scad|$OSCAD/Old/example024.scad|Menger sponge
scad-CSG|scad|$OSCAD/Basics/CSG.scad|CSG union/difference/intersection
scad-rotate_extrude|scad|$OSCAD/Basics/rotate_extrude.scad|rotate_extrude
occt-bottle|occt|$OCC/occ/bottle.brep|OCCT tutorial bottle (fillets, thread)
occt-CrankArm|occt|$OCC/occ/CrankArm.brep|crank arm
occt-Pump_Nut|occt|$OCC/occ/Pump_Nut.brep|pump nut
occt-Pump_TopCover|occt|$OCC/occ/Pump_TopCover.brep|pump top cover
occt-Motor-c|occt|$OCC/occ/Motor-c.brep|motor casing
occt-Axis_of_bearing|occt|$OCC/occ/Axis_of_bearing.brep|bearing axis (cylinders)
occt-Top|occt|$OCC/occ/Top.brep|top
occt-Bottom|occt|$OCC/occ/Bottom.brep|bottom
occt-screw|occt|$OCC/step/screw.step|screw (STEP)
occt-linkrods|occt|$OCC/step/linkrods.step|link rods (STEP)
occt-bearing|occt|$OCC/iges/bearing.iges|bearing (IGES)
gmsh-component8|gmsh|$GD/doc/gmsh/demos/boolean/component8.step.gz|STEP component
gmsh-as1-tu-203|gmsh|$GD/doc/gmsh/demos/boolean/as1-tu-203.stp.gz|STEP assembly
gmsh-fillet|gmsh|$GD/doc/gmsh/demos/boolean/fillet.geo|OCC fillet demo
gmsh-fillet2|gmsh|$GD/doc/gmsh/demos/boolean/fillet2.geo|OCC fillet demo
gmsh-chamfer|gmsh|$GD/doc/gmsh/demos/boolean/chamfer.geo|OCC chamfer demo
gmsh-pipe|gmsh|$GD/doc/gmsh/demos/boolean/pipe.geo|OCC pipe sweep
gmsh-twist|gmsh|$GD/doc/gmsh/demos/boolean/twist.geo|OCC twisted extrusion
gmsh-thrusections|gmsh|$GD/doc/gmsh/demos/boolean/thrusections.geo|OCC loft
gmsh-boolean|gmsh|$GD/doc/gmsh/demos/boolean/boolean.geo|OCC boolean demo
gmsh-lever|stl|$GD/converters/stl_to_cartesian/lever.stl.gz|lever STL
gmsh-object|stl|$GD/doc/gmsh/demos/api/object.stl.gz|object STL of the API demo
occt-stl-propeller|stl|$OCC/stl/propeller.stl|propeller (OCCT's sample STL)
occt-stl-sh1|stl|$OCC/stl/sh1.stl|sh1 (OCCT's sample STL)
occt-stl-sh2|stl|$OCC/stl/sh2.stl|sh2 (OCCT's sample STL)
occt-stl-shape|stl|$OCC/stl/shape.stl|shape (OCCT's sample STL)
occt-stl-TR12J|stl|$OCC/stl/TR12J_OCC.stl|TR12J (OCCT's sample STL)
occt-stl-bearing|stl|$OCC/stl/bearing.stl|bearing (OCCT's sample STL)
occt-stl-video_part|stl|$OCC/stl/video_part.stl|video part (OCCT's sample STL)
occt-stl-head|stl|$OCC/stl/head.stl|head (OCCT's sample STL)
occt-stl-motor|stl|$OCC/stl/motor.stl|motor (OCCT's sample STL)
"

# The unseen set. Sources are PACKAGE:PATH inside the unpacked package; kinds
# debstl (an STL as shipped), debocct (a STEP or BREP, or PATH:MEMBER for a
# .brp inside a FreeCAD document, a zip; then the occt recipe), debscad
# (openscad -o in the file's folder) and debscadline (PACKAGE:LIBRARY_DIR:a
# one-line OpenSCAD program using that library).
FC=freecad-common:/usr/share/freecad/Mod
PS=prusa-slicer:/usr/share/PrusaSlicer
OT=openscad-testing-data:/usr/share/openscad/testdata/scad
MCAD='openscad-mcad:/usr/share/openscad/libraries:use <MCAD/involute_gears.scad>;'
UNSEEN="
netgen-frame|debocct|netgen-doc:/usr/share/doc/netgen/examples/frame.step|CAD frame (STEP), long thin triangles
netgen-hinge|debstl|netgen-doc:/usr/share/doc/netgen/examples/hinge.stl|CAD hinge
netgen-part1|debstl|netgen-doc:/usr/share/doc/netgen/examples/part1.stl|CAD part
prusa-M3x10_screw|debstl|$PS/shapes/M3x10_screw.stl|threaded screw
prusa-M3_hex_nut|debstl|$PS/shapes/M3_hex_nut.stl|hex nut (threaded hole)
prusa-OTHER_recycling|debstl|$PS/shapes/OTHER_recycling_symbol.stl|embossed symbol with text
prusa-cylinder|debstl|$PS/shapes/cylinder.stl|cylinder, every triangle under 10 deg
prusa-torus|debstl|$PS/shapes/torus.stl|smooth torus
prusa-bunny|debstl|$PS/shapes/bunny.stl|coarse scanned bunny
prusa-cone|debstl|$PS/shapes/cone.stl|cone
prusa-helper_disk|debstl|$PS/shapes/helper_disk.stl|thin disk
prusa-rr-vc-300|debstl|$PS/profiles/RatRig/rr-vc-300.stl|printer bed plate with holes
prusa-aq_bed|debstl|$PS/profiles/TriLAB/aq_bed.stl|thin printer bed sheet
prusa-sl1_bed|debstl|$PS/profiles/PrusaResearch/sl1_bed.stl|printer bed
prusa-ender3_bed|debstl|$PS/profiles/Creality/ender3_bed.stl|printer bed, min angle 0.001 deg
cura-nozzle|debstl|cura:/usr/lib/cura/plugins/SimulationView/resources/nozzle.stl|print nozzle
cura-tronxy|debstl|cura:/usr/share/cura/resources/meshes/tronxy.stl|printer bed model
cura-BIQU_SSS|debstl|cura:/usr/share/cura/resources/meshes/BIQU_SSS.stl|printer bed
freecad-CAP_50SGV|debocct|$FC/Idf/Idflibs/CAP_50SGV_8_10.stp|SMD capacitor, several solids
freecad-TCMT1107_4|debocct|$FC/Idf/Idflibs/TCMT1107_4.stp|SMD package
freecad-RLF_7030|debocct|$FC/Idf/Idflibs/RLF_7030.stp|SMD inductor
freecad-Drilling_1|debocct|$FC/Path/PathTests/Drilling_1.FCStd:PartShape.brp|CAD block with drilled holes
freecad-test_holes00|debocct|$FC/Path/PathTests/test_holes00.fcstd:PartShape.brp|plate with many holes
freecad-thread-mill|debocct|$FC/Path/Tools/Shape/thread-mill.fcstd:PartShape.brp|revolved tool bit
freecad-bullnose|debocct|$FC/Path/Tools/Shape/bullnose.fcstd:PartShape.brp|revolved tool bit
oscadtest-rotate_extrude|debscad|$OT/3D/features/rotate_extrude-tests.scad|several rotate_extrude solids
oscadtest-difference|debscad|$OT/3D/features/difference-tests.scad|CSG differences
oscadtest-linear_extrude|debscad|$OT/3D/features/linear_extrude-tests.scad|linear extrusions
mcad-gear|debscadline|$MCAD gear(number_of_teeth=17, circular_pitch=500, bore_diameter=5, hub_diameter=15, rim_width=5, hub_thickness=10, rim_thickness=8, gear_thickness=4, circles=5);|involute gear with holes
mcad-bevel|debscadline|$MCAD test_bevel_gear();|bevel gear
"

# The fresh set: kind cgal as above (data.tar.gz is libcgal-demo's), debcad
# (PACKAGE:PATH, a STEP file read with the reader's defaults: all solids,
# 1e-3 of the diagonal, 0.5 rad). Only the candidates that passed the check:
# 13 more CGAL meshes and 9 models of assimp-testmodels are open,
# non-manifold or self-intersecting.
KI=kicad-packages3d:/usr/share/kicad/3dmodels
FRESH="
cgal2-armadillo|cgal|data/meshes/armadillo.off|scanned armadillo
cgal2-dino|cgal|data/meshes/dino.off|dinosaur
cgal2-homer|cgal|data/meshes/homer.off|cartoon figure
cgal2-helmet|cgal|data/meshes/helmet.off|coarse helmet
cgal2-blobby|cgal|data/meshes/blobby.off|smooth blob
cgal2-anchor_dense|cgal|data/meshes/anchor_dense.off|CAD anchor, denser
cgal2-refined_elephant|cgal|data/meshes/refined_elephant.off|organic, refined
cgal2-fandisk_large|cgal|data/meshes/fandisk_large.off|CAD fan disk, denser
cgal2-pinion_small|cgal|data/meshes/pinion_small.off|CAD pinion, coarser
cgal2-rotor_small|cgal|data/meshes/rotor_small.off|CAD rotor, coarser
cgal2-itemb|cgal|data/meshes/itemb.off|coarse CAD part
cgal2-retinal|cgal|data/meshes/retinal.off|smooth closed surface
cgal2-bunny00|cgal|data/meshes/bunny00.off|scanned bunny
ccx-halter|debcad|calculix-cgx-examples:/usr/share/doc/calculix-cgx-examples/examples/cad/halter.stp|CAD bracket
kicad-battery1058|debcad|$KI/Battery.3dshapes/BatteryHolder_Keystone_1058_1x2032.step|battery holder
kicad-buzzer12|debcad|$KI/Buzzer_Beeper.3dshapes/Buzzer_12x9.5RM7.6.step|buzzer
kicad-sma|debcad|$KI/Connector_Coaxial.3dshapes/SMA_Amphenol_132291_Vertical.step|SMA connector
kicad-dsub9|debcad|$KI/Connector_Dsub.3dshapes/DSUB-9_Female_Horizontal_P2.77x2.84mm_EdgePinOffset9.40mm.step|D-sub connector
kicad-jstxh2|debcad|$KI/Connector_JST.3dshapes/JST_XH_B2B-XH-A_1x02_P2.50mm_Vertical.step|JST connector
kicad-usbA|debcad|$KI/Connector_USB.3dshapes/USB_A_TE_292303-7_Horizontal.step|USB-A connector
kicad-hc49u|debcad|$KI/Crystal.3dshapes/Crystal_HC49-U_Vertical.step|crystal
kicad-fuseholder|debcad|$KI/Fuse.3dshapes/Fuseholder_Cylinder-5x20mm_Bulgin_FX0456_Vertical_Closed.step|fuse holder
kicad-heatsink125|debcad|$KI/Heatsink.3dshapes/Heatsink_125x35x50mm_3xFixationM3.step|heatsink, many fins
kicad-heatsinkAAVID|debcad|$KI/Heatsink.3dshapes/Heatsink_AAVID_573300D00010G_TO-263.step|heatsink
kicad-heatsinkHS132|debcad|$KI/Heatsink.3dshapes/Heatsink_Stonecold_HS-132_32x14mm_2xFixation1.5mm.step|heatsink
"
[ "$SET" = unseen ] && CANDIDATES="$UNSEEN"
[ "$SET" = fresh ] && CANDIDATES="$FRESH"

tar xzf "$CGAL_DATA" -C "$WORK" data/meshes
export LD_LIBRARY_PATH="$WORK/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

occt_mesh() {  # name model-file -> writes $WORK/raw/name.stl (OCCT's incmesh, then writestl)
    local name="$1" model="$2" read
    case "$model" in
        *.brep|*.brp) read="restore $model s" ;;
        *.step|*.stp) read="testreadstep $model s" ;;
        *.iges|*.igs) read="igesbrep $model s *" ;;
    esac
    cat > "$WORK/raw/$name.tcl" <<TCL
pload MODELING DATAEXCHANGE
$read
set b [bounding s]
set d [expr sqrt(pow([lindex \$b 3]-[lindex \$b 0],2)+pow([lindex \$b 4]-[lindex \$b 1],2)+pow([lindex \$b 5]-[lindex \$b 2],2))]
incmesh s [expr \$d/200.0] -a 20
writestl s $WORK/raw/$name.stl 0
exit
TCL
    (cd "$WORK/raw" && timeout 300 occt-draw -b -f "$name.tcl" </dev/null) >"$WORK/raw/$name.log" 2>&1
}

scad_mesh() {  # name scad-file -> writes $WORK/raw/name.stl (openscad in the file's folder)
    (cd "$(dirname "$2")" && timeout 300 openscad -o "$WORK/raw/$1.stl" "$2") >"$WORK/raw/$1.log" 2>&1
}

# package [file...] -> prints the folder it is unpacked in (downloaded once, not
# installed); with files, only those: kicad-packages3d is 5 GB unpacked
deb_root() {
    local pkg="$1" dir="$WORK/deb/$1" deb f need=0
    shift
    [ -e "$dir/.unpacked" ] || need=1
    [ $# = 0 ] && [ -s "$dir/.unpacked" ] && need=1  # unpacked in part before
    for f in "$@"; do [ -e "$dir$f" ] || need=1; done
    if [ $need = 1 ]; then
        rm -rf "$dir" && mkdir -p "$WORK/debs" "$dir"
        ls "$WORK/debs/${pkg}_"*.deb >/dev/null 2>&1 \
            || (cd "$WORK/debs" && apt-get download "$pkg") >"$WORK/debs/$pkg.log" 2>&1 || return 1
        deb="$(ls "$WORK/debs/${pkg}_"*.deb | head -n 1)"
        if [ $# = 0 ]; then dpkg-deb -x "$deb" "$dir" || return 1
        else dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$dir" "${@/#/.}" || return 1; fi
        echo "$*" > "$dir/.unpacked"
    fi
    echo "$dir"
}

if [ "$SET" = fresh ]; then
    # the plugin's CAD reader without ParaView: the same triangles, written exactly
    cat > "$WORK/cad2off.cpp" <<'CPP'
#include "CADTessellation.h"
#include "OffFormat.h"
#include <cstdio>
#include <fstream>
int main(int argc, char** argv)
{
  if (argc != 3) return std::fprintf(stderr, "usage: cad2off IN OUT.off\n"), 2;
  const ptm::CADSurface r = ptm::readCADSurface(argv[1], ptm::CADReadOptions());
  for (const std::string& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (!r.ok) return std::fprintf(stderr, "%s\n", r.error.c_str()), 1;
  std::ofstream out(argv[2]);
  ptm::writeOff(out, r.surface);
  return out ? 0 : 1;
}
CPP
    CORE="$HERE/../../Filters/Core"
    g++ -O2 -std=c++17 -I"$CORE/common" -I"$CORE/input" -isystem /usr/include/opencascade -o "$WORK/cad2off" \
        "$WORK/cad2off.cpp" "$CORE/input/CADTessellation.cpp" "$CORE/input/OffFormat.cpp" \
        -lTKSTEP -lTKIGES -lTKXSBase -lTKMesh -lTKTopAlgo -lTKBRep -lTKG3d -lTKGeomBase -lTKMath -lTKernel
    # one pass over each package's data for all its files
    for pkg in $(sed -n 's/^[^|]*|debcad|\([^:]*\):.*/\1/p' <<<"$CANDIDATES" | sort -u); do
        deb_root "$pkg" $(sed -n "s/^[^|]*|debcad|$pkg:\([^|]*\)|.*/\1/p" <<<"$CANDIDATES") >/dev/null || true
    done
fi

tessellate() {  # name kind source -> prints the raw file, or fails
    local name="$1" kind="$2" src="$3" raw="$WORK/raw/$1.stl" root rest
    case "$kind" in
        deb*)
            rest="${src#*:}"
            if [ "$kind" = debcad ]; then root="$(deb_root "${src%%:*}" "$rest")" || return 1
            else root="$(deb_root "${src%%:*}")" || return 1; fi ;;
    esac
    case "$kind" in
        cgal) raw="$WORK/$src" ;;
        stl) gzip -dcf "$src" > "$raw" ;;
        scad) scad_mesh "$name" "$src" ;;
        occt) occt_mesh "$name" "$src" ;;
        gmsh)
            local in="$src"
            case "$src" in *.gz) in="$WORK/raw/$(basename "${src%.gz}")"; gzip -dc "$src" > "$in" ;; esac
            (cd "$(dirname "$in")" && timeout 300 gmsh "$in" -2 -nt 1 -format stl -save_all -o "$raw") \
                >"$WORK/raw/$name.log" 2>&1 ;;
        debstl) cp "$root$rest" "$raw" ;;
        debcad)
            raw="$WORK/raw/$name.off"
            "$WORK/cad2off" "$root$rest" "$raw" >"$WORK/raw/$name.log" 2>&1 ;;
        debscad) scad_mesh "$name" "$root$rest" ;;
        debocct)
            case "$rest" in
                *:*)  # a member of a FreeCAD document (a zip)
                    unzip -p "$root${rest%%:*}" "${rest#*:}" > "$WORK/raw/$name.brp"
                    occt_mesh "$name" "$WORK/raw/$name.brp" ;;
                *) occt_mesh "$name" "$root$rest" ;;
            esac ;;
        debscadline)  # LIBRARY_DIR:PROGRAM
            printf '%s\n' "${rest#*:}" > "$WORK/raw/$name.scad"
            OPENSCADPATH="$root${rest%%:*}" scad_mesh "$name" "$WORK/raw/$name.scad" ;;
    esac
    [ -s "$raw" ] && echo "$raw"
}

TSV="$OUT/corpus.tsv"
printf 'name\tstatus\treason\tpoints\ttriangles\tvolume\tmin_triangle_angle\tshare_triangles_below_10\tkind\tsource\tnote\n' > "$TSV"
good=0
while IFS='|' read -r name kind src note; do
    [ -z "$name" ] && continue
    case "$kind" in deb*) ;; *) src="$(eval echo "$src")" ;; esac
    status=dirty reason="" points="" tris="" vol="" amin="" a10=""
    off="$WORK/$name.off"
    if raw="$(tessellate "$name" "$kind" "$src")" && [ -n "$raw" ] \
        && $PY "$TOOL" normalize "$raw" "$off" >"$WORK/raw/$name.normalize.log" 2>&1; then
        check="$("$WORK/check_surface" "$off")"
        st="$($PY "$TOOL" stats "$off")"
        read -r points tris vol amin a10 <<<"$($PY -c 'import json,sys; s=json.loads(sys.argv[1]); print(s["points"], s["triangles"], "%.9g" % s["volume"], "%.3f" % s["min_triangle_angle"], "%.4f" % s["share_triangles_below_10"])' "$st")"
        reason="$($PY -c '
import json, sys
c = json.loads(sys.argv[1])
r = []
if c["boundary_edges"]: r.append("open: %d boundary edges" % c["boundary_edges"])
if c["nonmanifold_edges"]: r.append("%d non-manifold edges" % c["nonmanifold_edges"])
if c["misoriented_edges"]: r.append("%d inconsistently oriented edges" % c["misoriented_edges"])
if not c["polygon_mesh"] and not r: r.append("non-manifold vertex")
if c["self_intersecting_pairs"] > 0: r.append("self-intersecting: %d triangle pairs" % c["self_intersecting_pairs"])
if c["volume"] <= 0 and not r: r.append("inside out or no volume (%g)" % c["volume"])
print("; ".join(r))' "$check")"
        if [ -z "$reason" ]; then
            status=good; reason=ok; good=$((good + 1)); cp "$off" "$OUT/$name.off"
        else
            cp "$off" "$OUT/dirty/$name.off"
        fi
    else
        reason="tessellation or reading failed (see .work/raw/$name.*log)"
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$status" "$reason" "$points" "$tris" "$vol" \
        "$amin" "$a10" "$kind" "${src#$WORK/}" "$note" >> "$TSV"
    printf 'fetch: %-24s %-5s %s\n' "$name" "$status" "$reason"
done <<<"$CANDIDATES"
echo "fetch: $good good surfaces in $OUT (table: $TSV)"
