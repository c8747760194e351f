#!/usr/bin/env bash
# The iceResistance function object's wall load against known answers
# (case wallLoad: 10 mm granite cubes, m = 2700 x 1e-6 = 2.7e-3 kg, on the
# plane wall 'plate', normal +z; resistance direction (0 0 -1)):
#   pushed  - one cube pressed on the plate by a body force of 50 m/s2
#             (gravity (0 0 -50)): at rest the load is m g = 0.135 N, all of
#             it normal (friction < 1e-9 N), one contact; the MSER-5 steady
#             mean of Rice within 0.1 % of m g
#   layer   - 30 cubes dropped on the plate: the steady mean of the load
#             within 0.5 % of the layer's weight 30 m g = 0.79461 N
#   incline - gravity tilted 30 deg about y, mu = 0.3 < tan 30: the cube
#             slides; at every sample after 0.02 s |friction| = mu |normal|
#             within 1e-4 relative, and the normal load = m g cos 30 within
#             0.5 % after the landing bounce (t >= 0.05 s)
. "$(dirname "$0")/common.sh"

kind="${1:?usage: demFoam_iceResistance.sh pushed|layer|incline}"

copyCase wallLoad
case "$kind" in
    pushed)
        setEntry constant/demProperties gravity "(0 0 -50)"
        ;;
    layer)
        setEntry constant/demProperties insertion \
            "{ layer { type randomFill; particleType cubes; number 30; seed 4;
               region { type box; min (-0.05 -0.05 0); max (0.05 0.05 0.06); } } }"
        setEntry system/controlDict endTime 0.6
        ;;
    incline)
        setEntry constant/demProperties gravity "(4.905 0 -8.4957139)"
        ;;
    *)
        fail "unknown variant $kind"
        ;;
esac

demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam failed"; }
dat=postProcessing/resistance/0/resistance.dat
mean=postProcessing/resistance/0/resistanceMean.dat
[ -f "$dat" ] || fail "no $dat"
[ -f "$mean" ] || fail "no $mean"
grep -q "^Rice " "$mean" || fail "no Rice line in $mean"
if python3 -c "import matplotlib" 2>/dev/null || /usr/bin/python3 -c "import matplotlib" 2>/dev/null
then
    [ -s postProcessing/resistance/0/resistance.png ] || fail "no plot (resistance.png)"
fi

# meanOf QUANTITY: its steady mean
meanOf() { awk -v q="$1" '$1 == q { print $2 }' "$mean"; }

# Every sample after t0: the awk expression test (columns by header name)
# must hold; prints the worst value of the expression measure
checkRows()
{
    awk -v t0="$1" -v tol="$3" '
        /^# time/ { for (i = 2; i <= NF; i++) c[$i] = i - 1; next }
        /^#/ { next }
        $1 >= t0 && $c["iceSteps"] > 0 {
            n++
            fx = $c["FiceFriction_x"]; fy = $c["FiceFriction_y"]; fz = $c["FiceFriction_z"]
            nx = $c["FiceNormal_x"]; ny = $c["FiceNormal_y"]; nz = $c["FiceNormal_z"]
            F = sqrt(fx*fx + fy*fy + fz*fz); N = sqrt(nx*nx + ny*ny + nz*nz)
            v = '"$2"'
            if (v < 0) v = -v
            if (v > worst) worst = v
        }
        END { printf "%d samples, worst %.3g (tolerance %g)\n", n, worst, tol
              exit (n < 10 || worst > tol) }' "$dat"
}

m=2.7e-3
case "$kind" in
    pushed)
        R=$(meanOf Rice)
        echo "Rice steady mean $R N, expected m g = $(awk -v m=$m 'BEGIN { print m*50 }') N"
        awk -v r="$R" -v m=$m 'BEGIN { e = (r - m*50)/(m*50); if (e < 0) e = -e; exit !(e < 1e-3) }' \
            || fail "Rice $R is not m g = 0.135 N within 0.1 %"
        checkRows 0.2 "F" 1e-9 || fail "frictional load on a cube at rest"
        checkRows 0.2 '$c["contacts"] - 1' 1e-12 || fail "not one contact"
        ;;
    layer)
        R=$(meanOf Rice)
        W=$(awk -v m=$m 'BEGIN { printf "%.6g", 30*m*9.81 }')
        echo "Rice steady mean $R N, the layer's weight $W N ($(awk '$1 == "Rice" { print "from t = " $5 ", " $4 " samples" }' "$mean"))"
        awk -v r="$R" -v w="$W" 'BEGIN { e = (r - w)/w; if (e < 0) e = -e; exit !(e < 5e-3) }' \
            || fail "Rice $R is not the weight $W within 0.5 %"
        ;;
    incline)
        checkRows 0.02 "F/N - 0.3" 1e-4 || fail "friction is not mu x normal force"
        checkRows 0.05 "(N - $m*9.81*0.8660254)/($m*9.81*0.8660254)" 5e-3 \
            || fail "normal load is not m g cos 30"
        ;;
esac
echo "PASS: iceResistance $kind"
