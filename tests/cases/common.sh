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
