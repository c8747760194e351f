"""Water balance of a demInterFoam tutorial run: the water volume
int eps alpha dV (postProcessing/demInterFoam/<t0>/waterVolume.dat, written
by the solver every step) plus the water that left through the open top
(postProcessing/waterOut/<t0>/surfaceFieldValue.dat: sum of alphaPhi0.water
over the patch, every step, times the step) against the start."""
import os


def _rows(path):
    return [[float(x) for x in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]


def balance(case, dt, fluxes=("waterOut",)):
    """(rows of (t, W, out, W + out, minAlpha, maxAlpha), W0); out is the
    cumulative outflow through the patches of the surfaceFieldValue
    function objects named in `fluxes` (each the sum of alphaPhi0.water over
    its patch, times the fixed step dt; inflow counts negative), or with dt
    None the solver's own (waterVolume.dat's last column, whole boundary)."""
    W = []
    base = os.path.join(case, "postProcessing", "demInterFoam")
    for t0 in sorted(os.listdir(base), key=float):
        W += _rows(os.path.join(base, t0, "waterVolume.dat"))
    if dt is None:
        # The solver's own column 7: the water out through the boundary in
        # each step, a volume (any time step: adjustTimeStep)
        out, res = 0.0, []
        for r in W:
            out += r[6]
            res.append((r[0], r[1], out, r[1] + out, r[2], r[3]))
        return res, W[0][1]
    flux = {}
    for name in fluxes:
        base = os.path.join(case, "postProcessing", name)
        for t0 in sorted(os.listdir(base), key=float):
            for r in _rows(os.path.join(base, t0, "surfaceFieldValue.dat")):
                k = round(r[0]/dt)
                flux[k] = flux.get(k, 0.0) + r[1]
    # W0: the volume before the first step (the first row is after it, so
    # add back that step's outflow: none, the water starts away from the top)
    W0 = W[0][1]
    out, res = 0.0, []
    for r in W:
        out += flux.get(round(r[0]/dt), 0.0)*dt
        res.append((r[0], r[1], out, r[1] + out, r[2], r[3]))
    return res, W0
