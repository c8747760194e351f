#!/usr/bin/env bash
# demFoam must stop (non-zero exit) on bad input with a message naming the
# file at fault (demProperties, or the STL) and the entry.
#
#   demFoam_badInput.sh missingKey|illTypedKey|unknownLaw|missingStl|
#                       malformedStl|unstableTimeStep|indivisibleDeltaT|
#                       twistingWithoutCoefficient|negativeTwistingFriction|
#                       misspelledTopKey|misspelledWallKey|misspelledInsertionKey|
#                       negativeActiveUntil|negativeGap|pairRestitution|
#                       tinyTimeStep|negativeDeltaT|listOverlap|listBehindWall|
#                       sliverShape|approachWithoutVelocity|
#                       approachOutsideRegion|approachWithoutHeight|
#                       approachMixedShapes
. "$(dirname "$0")/common.sh"

kind="$1"
copyCase settlingSpheres
props=constant/demProperties

addMeshWall()
{
    setEntry $props walls/box "{ type mesh; file \"$1\"; material steel; }"
}

case "$kind" in
missingKey)
    sed -i '/^timeStep/d' $props
    expectFile="constant/demProperties"; expectEntry="timeStep" ;;
illTypedKey)
    sed -i 's/^timeStep .*/timeStep        abc;/' $props
    expectFile="constant/demProperties"; expectEntry="timeStep" ;;
unknownLaw)
    setEntry $props contactModel/law frictionlessMagic
    expectFile="constant/demProperties"; expectEntry="law"
    # the valid names are listed too
    expectAlso="hertzMindlin" ;;
missingStl)
    addMeshWall missing.stl
    expectFile="constant/triSurface/missing.stl"; expectEntry="walls/box/file" ;;
malformedStl)
    mkdir -p constant/triSurface
    printf 'solid broken\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 zero\n' \
        > constant/triSurface/broken.stl
    head -c 300 /dev/urandom >> constant/triSurface/broken.stl
    addMeshWall broken.stl
    expectFile="constant/triSurface/broken.stl"; expectEntry="walls/box/file" ;;
unstableTimeStep)
    # 1e-3 s is far above 20 % of the Rayleigh time (~4e-5 s) of these beads
    setEntry $props timeStep 1e-3
    expectFile="constant/demProperties"; expectEntry="timeStep"
    expectAlso="stability" ;;
indivisibleDeltaT)
    # deltaT 0.002 / 3e-5 = 66.67 steps
    setEntry $props timeStep 3e-5
    expectFile="constant/demProperties"; expectEntry="timeStep"
    expectAlso="deltaT" ;;
twistingWithoutCoefficient)
    # twisting resistance switched on: every interaction needs its mu_t
    setEntry $props contactModel/twisting yes
    expectFile="constant/demProperties"; expectEntry="twistingFriction" ;;
negativeTwistingFriction)
    setEntry $props contactModel/twisting yes
    setEntry $props interactions/default/twistingFriction -0.1
    expectFile="constant/demProperties"; expectEntry="twistingFriction"
    expectAlso=">= 0" ;;
misspelledTopKey)
    # used to be ignored: gravity then defaults to (0 0 -9.81)
    sed -i 's/^gravity /gravty  /' $props
    expectFile="constant/demProperties"; expectEntry="gravty"
    expectAlso="did you mean 'gravity'" ;;
misspelledWallKey)
    # used to be ignored: the wall then stays for the whole run
    setEntry $props walls/floor/activeUntill 0.005
    expectFile="constant/demProperties"; expectEntry="walls/floor/activeUntill"
    expectAlso="did you mean 'activeUntil'" ;;
misspelledInsertionKey)
    setEntry $props insertion/beads/velocty "(0 0 -1)"
    expectFile="constant/demProperties"; expectEntry="insertion/beads/velocty"
    expectAlso="Valid entries of 'insertion/beads'" ;;
negativeActiveUntil)
    # used to be accepted (the wall removed at the first step)
    setEntry $props walls/floor/activeUntil -1
    expectFile="constant/demProperties"; expectEntry="walls/floor/activeUntil" ;;
negativeGap)
    # used to be reported as insertion/beads/number
    setEntry $props insertion/beads/gap -1e-3
    expectFile="constant/demProperties"; expectEntry="insertion/beads/gap" ;;
pairRestitution)
    # used to be reported as interactions/restitution, without the pair
    setEntry $props interactions/glassOnSteel/restitution 1.5
    expectFile="constant/demProperties"; expectEntry="interactions/glassOnSteel/restitution"
    expectAlso="(0, 1]" ;;
tinyTimeStep)
    # used to be refused as "does not divide" (1e-12 for 1e-5: a units slip)
    setEntry $props timeStep 1e-12
    expectFile="constant/demProperties"; expectEntry="timeStep"
    expectAlso="check the units" ;;
negativeDeltaT)
    # used to be refused as "does not divide"
    setEntry system/controlDict deltaT -0.002
    expectFile="system/controlDict"; expectEntry="deltaT"
    expectAlso="positive" ;;
listOverlap)
    # two beads at one point used to never interact
    setEntry $props insertion "{ pair { type list; particleType beads; particles ( { position (0.01 0.01 0.01); } { position (0.01 0.01 0.01); } { position (0.02 0.02 0.01); } ); } }"
    expectFile="constant/demProperties"; expectEntry="insertion/pair/particles[0]"
    expectAlso="insertion/pair/particles[1]" ;;
listBehindWall)
    # a bead below the floor used to be driven downwards
    setEntry $props insertion "{ low { type list; particleType beads; particles ( { position (0.01 0.01 0.01); } { position (0.01 0.02 -0.001); } ); } }"
    expectFile="constant/demProperties"; expectEntry="insertion/low/particles[1]"
    expectAlso="behind plane wall 'floor'" ;;
sliverShape)
    # a 50:50:1 plate (sphericity 0.16) has no stable time step
    setEntry $props contactModel "{ law overlapVolume; volumetricStiffness 1e10; }"
    setEntry $props particleTypes/flake "{ shape polyhedron; material glass; geometry { type box; size (0.01 0.01 0.0002); } }"
    expectFile="constant/demProperties"; expectEntry="particleTypes/flake"
    expectAlso="sphericity" ;;
approachWithoutVelocity)
    # an approach region moves its particles at the inflow's velocity
    setEntry $props insertion "{ feed { type inflow; particleType beads; region { type box; min (0 0 0); max (0.02 0.02 0.01); } solidFraction 0.1;  approach { min (-0.01 -0.01 -0.01); max (0.03 0.03 0.02); height 0.005; } } }"
    expectFile="constant/demProperties"; expectEntry="insertion/feed/velocity" ;;
approachOutsideRegion)
    # blocks placed outside the approach box would fall at once
    setEntry $props insertion "{ feed { type inflow; particleType beads; region { type box; min (0 0 0); max (0.02 0.02 0.01); } solidFraction 0.1; velocity (0.1 0 0); approach { min (-0.01 -0.01 -0.01); max (0.01 0.03 0.02); height 0.005; } } }"
    expectFile="constant/demProperties"; expectEntry="insertion/feed/region"
    expectAlso="inside" ;;
approachWithoutHeight)
    setEntry $props insertion "{ feed { type inflow; particleType beads; region { type box; min (0 0 0); max (0.02 0.02 0.01); } solidFraction 0.1; velocity (0.1 0 0); approach { min (-0.01 -0.01 -0.01); max (0.03 0.03 0.02);  } } }"
    expectFile="constant/demProperties"; expectEntry="insertion/feed/approach/height" ;;
approachMixedShapes)
    # a floating layer places one kind: spheres or polyhedra, not both
    setEntry $props contactModel "{ law overlapVolume; volumetricStiffness 1e9; }"
    setEntry $props particleTypes/cube "{ shape polyhedron; material glass; geometry { type box; size (0.004 0.004 0.004); } }"
    setEntry $props insertion "{ feed { type inflow; particleTypes (beads cube); region { type box; min (0 0 0); max (0.02 0.02 0.01); } solidFraction 0.1; velocity (0.1 0 0); approach { min (-0.01 -0.01 -0.01); max (0.03 0.03 0.02); height 0.005; } } }"
    expectFile="constant/demProperties"; expectEntry="insertion/feed/approach"
    expectAlso="all spheres or all polyhedra" ;;
*)
    fail "unknown bad-input kind '$kind'" ;;
esac

setEntry system/controlDict endTime 0.01
demFoam > log.demFoam 2>&1
rc=$?
sed -n '/FOAM FATAL/,/FOAM exiting/p' log.demFoam

[ "$rc" -ne 0 ] || fail "demFoam exited with 0 on bad input ($kind)"
grep -q "FOAM FATAL" log.demFoam || { tail -20 log.demFoam; fail "no FOAM FATAL message ($kind)"; }
grep -qF "$testDir/settlingSpheres/$expectFile" log.demFoam \
    || fail "message does not name the file $expectFile ($kind)"
grep -qF "$expectEntry" log.demFoam \
    || fail "message does not name the entry $expectEntry ($kind)"
if [ -n "$expectAlso" ]
then
    grep -qiF "$expectAlso" log.demFoam || fail "message does not say '$expectAlso' ($kind)"
fi
echo "PASS: $kind: exit $rc, names $expectFile and $expectEntry"
