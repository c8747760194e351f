#!/usr/bin/env bash
# demFoam must stop (non-zero exit) on bad polyhedra input with a message
# naming the file at fault (demProperties, or the particle STL) and the entry.
#
#   polyhedra_badInput.sh nonConvexStl|degenerateStl|missingStl|
#       unknownGeometry|missingVolumetricStiffness|hertzWithPolyhedra|
#       tooManyFaces|diameterDistribution
. "$(dirname "$0")/common.sh"

kind="$1"
copyCase settlingRocks
props=constant/demProperties

# Particle type 'rocks' from an STL in constant/triSurface
stlRocks()
{
    setEntry $props particleTypes/rocks/geometry "{ type stl; file \"$1\"; scale 1e-3; }"
}

# ascii STL from "x y z" triangle triples on stdin
writeStl()
{
    mkdir -p constant/triSurface
    awk 'BEGIN { print "solid s" }
         { printf "facet normal 0 0 0\n outer loop\n  vertex %s %s %s\n  vertex %s %s %s\n  vertex %s %s %s\n endloop\nendfacet\n", $1,$2,$3,$4,$5,$6,$7,$8,$9 }
         END { print "endsolid s" }' > "constant/triSurface/$1"
}

case "$kind" in
nonConvexStl)
    # A unit cube whose top face is pushed in to a pyramid (closed, not convex)
    writeStl dented.stl <<'TRI'
0 0 0 1 1 0 1 0 0
0 0 0 0 1 0 1 1 0
0 0 0 1 0 0 1 0 1
0 0 0 1 0 1 0 0 1
1 0 0 1 1 0 1 1 1
1 0 0 1 1 1 1 0 1
1 1 0 0 1 0 0 1 1
1 1 0 0 1 1 1 1 1
0 1 0 0 0 0 0 0 1
0 1 0 0 0 1 0 1 1
0 0 1 1 0 1 0.5 0.5 0.3
1 0 1 1 1 1 0.5 0.5 0.3
1 1 1 0 1 1 0.5 0.5 0.3
0 1 1 0 0 1 0.5 0.5 0.3
TRI
    stlRocks dented.stl
    expectFile="constant/triSurface/dented.stl"; expectEntry="particleTypes/rocks/geometry/file"
    expectAlso="not convex" ;;
degenerateStl)
    # All points in one plane: no volume
    writeStl flat.stl <<'TRI'
0 0 0 1 0 0 1 1 0
0 0 0 1 1 0 0 1 0
0 0 0 2 0 0 0 1 0
TRI
    stlRocks flat.stl
    expectFile="constant/triSurface/flat.stl"; expectEntry="particleTypes/rocks/geometry/file" ;;
missingStl)
    stlRocks missing.stl
    expectFile="constant/triSurface/missing.stl"; expectEntry="particleTypes/rocks/geometry/file" ;;
unknownGeometry)
    setEntry $props particleTypes/rocks/geometry/type blob
    expectFile="constant/demProperties"; expectEntry="type"
    expectAlso="icosahedron" ;;
missingVolumetricStiffness)
    foamDictionary -entry contactModel/volumetricStiffness -remove $props >/dev/null \
        || fail "foamDictionary could not remove the entry"
    expectFile="constant/demProperties"; expectEntry="volumetricStiffness" ;;
hertzWithPolyhedra)
    setEntry $props contactModel/law hertzMindlin
    expectFile="constant/demProperties"; expectEntry="contactModel/law"
    expectAlso="overlapVolume" ;;
tooManyFaces)
    # the hull of 60 random points has ~110 faces, above the cap of 64
    setEntry $props particleTypes/rocks/geometry/points 60
    expectFile="constant/demProperties"; expectEntry="particleTypes/rocks/geometry"
    expectAlso="faces" ;;
diameterDistribution)
    setEntry $props insertion/rocks/diameterDistribution "{ type fixed; diameter 4e-3; }"
    expectFile="constant/demProperties"; expectEntry="insertion/rocks/diameterDistribution" ;;
*)
    fail "unknown bad-input kind '$kind'" ;;
esac

setEntry system/controlDict endTime 0.01
demFoam > log.demFoam 2>&1
rc=$?
sed -n '/FOAM FATAL/,/FOAM exiting/p' log.demFoam

[ "$rc" -ne 0 ] || fail "demFoam exited with 0 on bad input ($kind)"
grep -q "FOAM FATAL" log.demFoam || { tail -20 log.demFoam; fail "no FOAM FATAL message ($kind)"; }
grep -qF "$testDir/settlingRocks/$expectFile" log.demFoam \
    || fail "message does not name the file $expectFile ($kind)"
grep -qF "$expectEntry" log.demFoam \
    || fail "message does not name the entry $expectEntry ($kind)"
if [ -n "$expectAlso" ]
then
    grep -qiF "$expectAlso" log.demFoam || fail "message does not say '$expectAlso' ($kind)"
fi
echo "PASS: $kind: exit $rc, names $expectFile and $expectEntry"
