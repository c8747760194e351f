# Hedra case tests: shared set-up, sourced by the test scripts.
#
# - sources etc/bashrc; skips (exit 77, CTest SKIP_RETURN_CODE) when the
#   OpenFOAM environment is not installed at all (etc/install-dependencies
#   not run), but FAILS when demFoam is missing: Allwmake always builds it
# - makes a temporary folder (removed at exit unless HEDRA_KEEP_TEST_DIRS=1)
# - copyCase <case> copies tests/cases/<case> into it and cd's there

casesDir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)"
hedraRoot="$(cd "$casesDir/../.." && pwd -P)"

. "$hedraRoot/etc/bashrc" >/dev/null 2>&1 || true

if [ -z "$WM_PROJECT_DIR" ] || ! command -v foamDictionary >/dev/null 2>&1
then
    echo "SKIP: no OpenFOAM environment (run etc/install-dependencies, then"
    echo "      source etc/bashrc): case tests need OpenFOAM"
    exit 77
fi

if ! command -v demFoam >/dev/null 2>&1
then
    echo "FAIL: demFoam is not built (expected in $FOAM_USER_APPBIN):"
    echo "      ./Allwmake builds it"
    exit 1
fi

# libgomp's default spin-waiting makes the CPU back end crawl when other
# tests share the cores (ctest -j): wait passively unless told otherwise.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"

testDir="$(mktemp -d "${TMPDIR:-/tmp}/hedra-case.XXXXXX")"
if [ "${HEDRA_KEEP_TEST_DIRS:-0}" = 1 ]
then
    echo "test folder: $testDir (kept)"
else
    trap 'rm -rf "$testDir"' EXIT
fi

fail()
{
    echo "FAIL: $*"
    exit 1
}

copyCase()
{
    rm -rf "$testDir/$1"
    cp -r "$casesDir/$1" "$testDir/$1"
    cd "$testDir/$1" || fail "cannot enter $testDir/$1"
}

setEntry()
{
    # setEntry file entry value
    foamDictionary -entry "$2" -set "$3" "$1" >/dev/null \
        || fail "foamDictionary could not set $2 in $1"
}

# compareStates ONE_GO RESTARTED WHAT: pass when the two polyDEM state files are
# identical to the byte; otherwise print the largest relative difference and fail
compareStates()
{
    [ -f "$1" ] && [ -f "$2" ] || fail "missing state files ($1, $2)"
    if cmp -s "$1" "$2"
    then
        echo "PASS: restarted $3 is identical (bytes) to the one-go run"
        exit 0
    fi
    awk 'NR==FNR { for (i = 1; i <= NF; i++) v[FNR, i] = $i; next }
         { for (i = 1; i <= NF; i++) if ($i + 0 == $i) {
             d = $i - v[FNR, i]; if (d < 0) d = -d
             s = ($i < 0 ? -$i : $i); if (s < 1e-300) s = 1e-300
             if (d / s > m) m = d / s } }
         END { printf "largest relative difference %g\n", m }' "$1" "$2"
    fail "restarted $3 differs from the one-go run"
}

# checkBalance FILE: inserted - removed = particles on every line
checkBalance()
{
    awk '/^# time/ { for (i = 2; i <= NF; i++) c[$i] = i - 1; next }
         /^#/ { next }
         { n++
           if ($c["inserted"] - $c["removed"] != $c["particles"] || $c["balance"] != 0) {
               printf "line %d (t = %s): inserted %d - removed %d != particles %d\n",
                      n, $1, $c["inserted"], $c["removed"], $c["particles"]; bad = 1 } }
         END { if (n < 10) { print "only " n " lines"; bad = 1 }; exit bad }' "$1" \
        || fail "particle bookkeeping broken in $1"
}

# lastValue FILE NAME: the last line's value of column NAME
lastValue()
{
    awk -v want="$2" '/^# time/ { for (i = 2; i <= NF; i++) if ($i == want) k = i - 1; next }
                      /^#/ { next } { v = $k } END { print v }' "$1"
}
