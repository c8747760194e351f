"""Readers of the wet ball mill's results (plot.py, tabulate.py,
checkSlurry.py, voids.py, fluidSpeeds.py, poolAtRest.py): the chargeShape
monitor, the fluid's moment on the shell (forces function object), the
slurry volume (demInterFoam's waterVolume.dat), the dry tutorial's reference
table, the cell values of a written field. Plain python3."""
import glob
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
DRY_RESULTS = os.path.join(HERE, "..", "..", "demFoam", "ballMill", "reference", "results.md")
CHARGE_COLS = ("time shoulder toe toeBelow shoulderHeight toeHeight M xc yc wallTorque "
               "gravityTorque power powerGravity wallSteps dissipation wallWorkRate externalWorkRate energy").split()


def internal_field(path, width=1):
    """The internalField of an ASCII OpenFOAM field file: a list of floats
    (width 1) or of tuples of width floats (vectors); a uniform field gives
    its value (a float or a tuple); None when neither is found."""
    txt = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(?:scalar|vector)>\s*(\d+)\s*\(", txt)
    if m is None:
        u = re.search(r"internalField\s+uniform\s+(\([^()]*\)|[-+0-9.eE]+)", txt)
        if u is None:
            return None
        v = [float(x) for x in u.group(1).strip("()").split()]
        return v[0] if width == 1 else tuple(v)
    n = int(m.group(1))
    body = txt[m.end():]
    if width == 1:
        return [float(v) for v in body.split(None, n)[:n]]
    return [tuple(float(c) for c in v.split()) for v in re.findall(r"\(([^()]*)\)", body)[:n]]


def case_info(case):
    return dict(l.split()[:2] for l in open(os.path.join(case, "case.info")) if l.strip())


def _timedirs(pattern):
    return sorted(glob.glob(pattern), key=lambda p: float(p.split(os.sep)[-2]))


def charge_rows(case):
    """Rows of every postProcessing/charge/<t>/charge.dat (the dry filling
    and the wet run), sorted by time; and the column index."""
    rows = []
    for f in _timedirs(os.path.join(case, "postProcessing/charge/*/charge.dat")):
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(x) for x in line.split()])
    rows.sort()
    return rows, {n: k for k, n in enumerate(CHARGE_COLS)}


def charge_means(case):
    """The steady means of the wet run (its own chargeMean.dat, the last
    start time's)."""
    m = {}
    files = _timedirs(os.path.join(case, "postProcessing/charge/*/chargeMean.dat"))
    if not files:
        return m
    for line in open(files[-1]):
        if line.startswith("#") or not line.strip():
            continue
        q, v, e, n = line.split()
        m[q.split("[")[0]] = (float(v), float(e))
    return m


def fluid_torque(case, axis=2):
    """(t, T.a) of the forces function object 'fluidForces' (total moment,
    about CofR (0 0 0); a = +z)."""
    out = []
    for f in _timedirs(os.path.join(case, "postProcessing/fluidForces/*/moment.dat")):
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in re.sub(r"[()]", " ", line).split()]
            out.append((v[0], v[1 + axis]))
    return out


def water_rows(case):
    """Rows of postProcessing/demInterFoam/<t>/waterVolume.dat: t, water
    volume, min alpha, max alpha, solid volume, nParticles, water out."""
    rows = []
    for f in _timedirs(os.path.join(case, "postProcessing/demInterFoam/*/waterVolume.dat")):
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(x) for x in line.split()])
    return rows


def batch_means(samples, t0, t1, nb=8):
    """Mean over t0 <= t <= t1 of (t, v) samples and the standard error
    from nb contiguous batches (in time) of equal length."""
    sel = [(t, v) for t, v in samples if t0 - 1e-9 <= t <= t1 + 1e-9]
    if not sel:
        return float("nan"), float("nan"), []
    mean = sum(v for _, v in sel) / len(sel)
    batches = []
    for k in range(nb):
        a = t0 + (t1 - t0) * k / nb
        b = t0 + (t1 - t0) * (k + 1) / nb
        vs = [v for t, v in sel if (a <= t < b) or (k == nb - 1 and t == b)]
        if vs:
            batches.append(sum(vs) / len(vs))
    if len(batches) < 2:
        return mean, float("nan"), batches
    bm = sum(batches) / len(batches)
    sd = math.sqrt(sum((b - bm) ** 2 for b in batches) / (len(batches) - 1))
    return mean, sd / math.sqrt(len(batches)), batches


def dry_reference(case):
    """The dry tutorial's steady values of this mill (its reference table):
    dict name -> (value, error) for shoulder, toe, shoulderHeight,
    toeHeight, power [kW]."""
    if not os.path.isfile(DRY_RESULTS):
        return {}
    for line in open(DRY_RESULTS):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and cells[0] == case:
            out = {}
            for name, c in zip(("shoulder", "toe", "shoulderHeight", "toeHeight", "power"), cells[1:6]):
                v, e = c.split("+-")
                out[name] = (float(v), float(e))
            return out
    return {}
