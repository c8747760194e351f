#!/usr/bin/env python3
"""Bad input to the LIGGGHTS back end (demBackend liggghts) stops the run
with a message naming the file, and a non-zero exit, without hanging:

  1. inputScript names no file          -> FatalIOError naming the path
                                            and the entry inputScript
  2. script without the coupling fixes  -> FatalIOError naming the script
                                            and the fix lines to add
  3. script without atom_modify map     -> names atom_modify map array
  4. LIGGGHTS error inside the script   -> LIGGGHTS's own ERROR line,
     (an unknown command)                  copied to stderr with the script
  5. LIGGGHTS timestep not dividing deltaT -> FatalIOError naming the script
  6. case 2 on two ranks (mpirun -np 2)  -> stops, message, no hang
Each run has a 120 s limit (a hang fails the test).
"""
import os
import subprocess
import hedracase as hc
import liggghtscase as lc

BASE = """formulation setI;
voidFractionModel centre;
forceModels (SchillerNaumann pressureGradient);
"""
box = ((0, 0, 0), (0.02, 0.02, 0.02))


def make_case(name, script_kw, coupling=None, dt=1e-5):
    case = hc.workdir(f"liggghts-bad-{name}")
    hc.block_mesh(case, *box, (2, 2, 2),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.002, 1e-3, 1)
    hc.schemes_solution(case)
    hc.transport(case, 1e-6, 1000)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    if script_kw is not None:
        lc.script(case, box, dt, 2500, 2e-3, [(0.01, 0.01, 0.01)], floor_z=0.0,
                         **script_kw)
    hc.coupling(case, BASE + (coupling or lc.coupling_lines()))
    hc.run("blockMesh", case, "log.blockMesh")
    return case


def mutate(case, old, new):
    p = os.path.join(case, "constant/liggghts/in.liggghts")
    txt = open(p).read()
    assert old in txt, old
    open(p, "w").write(txt.replace(old, new))


results = []


def expect_failure(name, case, cmd, expect):
    try:
        rc = hc.run(cmd, case, "log.demPimpleFoam", check=False, timeout=120)
    except subprocess.TimeoutExpired:
        results.append(False)
        print(f"FAIL: {name}: no exit within 120 s (hang)")
        return
    log = open(os.path.join(case, "log.demPimpleFoam")).read()
    missing = [s for s in expect if s not in log]
    ok = rc != 0 and not missing
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {name}: exit {rc}"
          + (f", missing in the message: {missing}" if missing else ""))
    if not ok:
        i = log.find("FOAM FATAL")
        print(log[i:i + 1500] if i >= 0 else log[-1500:])


# 1. no script
case = make_case("missing", None)
expect_failure("missing script", case, "demPimpleFoam",
               ["constant/liggghts/in.liggghts", "does not exist", "inputScript",
                "liggghtsCoeffs"])

# 2. no coupling fixes
case = make_case("noFix", {"coupling": False})
script = os.path.join(case, "constant/liggghts/in.liggghts")
expect_failure("script without the coupling fix", case, "demPimpleFoam",
               [script, "couple/cfd couple_every 1 mpi", "couple/cfd/force"])

# 3. no atom map
case = make_case("noMap", {})
mutate(case, "atom_modify map array\n", "")
expect_failure("script without atom_modify map", case, "demPimpleFoam",
               ["in.liggghts", "atom_modify map array"])

# 4. an error inside LIGGGHTS
case = make_case("liggghtsError", {"extra": "fix nonsense all no/such/style\n"})
expect_failure("LIGGGHTS error in the script", case, "demPimpleFoam",
               ["LIGGGHTS stopped the run", "in.liggghts", "ERROR", "log.liggghts"])

# 5. timestep not dividing deltaT
case = make_case("timestep", {}, dt=3e-5)
expect_failure("timestep not dividing deltaT", case, "demPimpleFoam",
               ["LIGGGHTS timestep", "does not divide", "in.liggghts"])

# 6. case 2 on two ranks
case = make_case("noFixParallel", {"coupling": False})
hc.run("decomposePar", case, "log.decomposePar")
script = os.path.join(case, "constant/liggghts/in.liggghts")
expect_failure("script without the coupling fix, 2 ranks", case,
               "mpirun -np 2 demPimpleFoam -parallel",
               [script, "couple/cfd couple_every 1 mpi"])

hc.finish(results)
