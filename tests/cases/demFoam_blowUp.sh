#!/usr/bin/env bash
# A DEM run that would blow up stops with a FatalIOError naming the entry or
# the particle (id, type, position, velocity) and the likely cause -- never a
# signal (SIGFPE trap), a NaN that runs on, or exit 0 (hardening, item 2).
#
#   demFoam_blowUp.sh hugeVelocity|hugeOmega|drivenThroughFloor|
#                     softSpheres|softPolyhedra
#
#   hugeVelocity        a listed sphere with v = 1e200 m/s: refused at
#                       insertion (it would move further than its diameter in
#                       one step), naming the list entry
#   hugeOmega           a listed sphere with omega = 1e300 rad/s: refused at
#                       insertion (more than 1 rad per step)
#   drivenThroughFloor  a listed sphere shot at the floor at 100 m/s: 2 mm (half
#                       a diameter) per 2e-5 s step passes the insertion check,
#                       but it moves more than the neighbour skin (0.8 mm) in
#                       one step: the engine's guard stops the run, naming it
#   softSpheres         the beads 1e5 times softer (E 50 Pa): they sink into
#                       the floor and each other by more than a third of a
#                       radius, which the sample after each deltaT catches
#                       (Hertz: a bead's own weight alone gives 6 mm > r)
#   softPolyhedra       the settling rocks with a volumetric stiffness 1e5
#                       times lower (3e3 N/m3): a rock's weight needs an
#                       overlap of more than its own volume; the check at the
#                       write time catches the first rock past 10 %
. "$(dirname "$0")/common.sh"

kind="$1"
end=0.01
if [ "$kind" = softPolyhedra ]
then
    copyCase settlingRocks
else
    copyCase settlingSpheres
fi
props=constant/demProperties

listed()
{
    # listed VELOCITY OMEGA: one sphere 2 mm above the floor (id 0)
    foamDictionary -entry insertion -remove $props >/dev/null
    cat >> $props <<EOD
insertion
{
    shot
    {
        type            list;
        particleType    beads;
        particles
        (
            { position (0.015 0.015 0.004); velocity $1; omega $2; }
        );
    }
}
EOD
}

case "$kind" in
hugeVelocity)
    listed "(0 0 -1e200)" "(0 0 0)"
    expect=("insertion/shot/particles[0]/velocity" "moves particle 0 further than its diameter") ;;
hugeOmega)
    listed "(0 0 0)" "(1e300 0 0)"
    expect=("insertion/shot/particles[0]/omega" "by more than 1 rad in one DEM step") ;;
drivenThroughFloor)
    listed "(0 0 -100)" "(0 0 0)"
    expect=("unstable" "particle id 0 (type 'beads'" "more than the neighbour skin"
            "nearest plane wall 'floor'" "time step") ;;
softSpheres)
    end=0.1
    setEntry $props materials/glass/youngsModulus 50
    setEntry $props materials/steel/youngsModulus 200
    expect=("of a radius (more than 0.333" "passing through each other" "particle "
            "(type beads)" "timeStep") ;;
softPolyhedra)
    end=0.05
    setEntry $props contactModel/volumetricStiffness 3e3
    setEntry system/controlDict writeInterval 0.01
    expect=("overlap volume of more than 10 %" "passing through each other"
            "% of the smaller particle" "timeStep") ;;
*)
    fail "unknown blow-up kind '$kind'" ;;
esac

setEntry system/controlDict endTime $end
demFoam > log.demFoam 2>&1
rc=$?
sed -n '/FOAM FATAL/,/FOAM exiting/p' log.demFoam

[ "$rc" -ne 0 ] || fail "demFoam exited with 0 on a blow-up ($kind)"
[ "$rc" -lt 128 ] || { tail -30 log.demFoam; fail "demFoam died on signal $((rc - 128)) ($kind)"; }
grep -q "FOAM FATAL" log.demFoam || { tail -20 log.demFoam; fail "no FOAM FATAL message ($kind)"; }

grep -qF "constant/demProperties" log.demFoam || fail "message does not name constant/demProperties ($kind)"
for e in "${expect[@]}"
do
    grep -qF "$e" log.demFoam || fail "message does not say '$e' ($kind)"
done
grep -qiw "nan" log.demFoam && fail "a NaN was printed ($kind)"
echo "PASS: $kind: exit $rc, the message names: ${expect[*]}"
