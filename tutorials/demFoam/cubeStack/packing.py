#!/usr/bin/env python3
"""Cube stack: packing fraction and coordination number of the last written
state, and the kinetic energy against time (log scale).

    python3 packing.py [case] [boxSize] [edge]

Packing fraction (Monte Carlo, 2e5 points, inside test against every
polyhedron's face planes from polyhedra.vtp):
  - bulk: in the box x, y in [2a, L - 2a], z in [a, hTop - 2a] (a: edge,
    hTop: median height of the surface), away from the walls and the free
    surface;
  - bed: total particle volume / (L^2 hTop), walls and top layer included.
Coordination number from the engine's contact count (summary.dat, last line):
  Z = 2 contacts / particles (particle-particle) and with wall contacts.
Writes postProcessing/packing.dat and postProcessing/kineticEnergy.png.
Needs numpy (and matplotlib for the plot).
"""
import os
import re
import sys

import numpy as np

case = sys.argv[1] if len(sys.argv) > 1 else "."
L = float(sys.argv[2]) if len(sys.argv) > 2 else 0.04
a = float(sys.argv[3]) if len(sys.argv) > 3 else 0.005


def latestTime(case):
    times = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, d, "polyDEM")):
            times.append((t, d))
    return max(times)[1]


def vtpPolyhedra(path):
    text = open(path).read()
    def block(tag, name=None):
        if name:
            m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        else:
            m = re.search(r'<%s>\s*<DataArray[^>]*>(.*?)</DataArray>' % tag, text, re.S)
        return np.array(m.group(1).split(), dtype=float)
    pts = block("Points").reshape(-1, 3)
    conn = block(None, "connectivity").astype(int)
    offs = block(None, "offsets").astype(int)
    ids = block(None, "particleId").astype(int)
    polys = np.split(conn, offs[:-1])
    return pts, polys, ids


time = latestTime(case)
pts, polys, ids = vtpPolyhedra(os.path.join(case, time, "polyDEM", "polyhedra.vtp"))

# Per particle: face planes n.x <= d, centre, bounding radius, volume
particles = {}
for poly, pid in zip(polys, ids):
    particles.setdefault(pid, []).append(poly)
planes, centres, radii, volumes = [], [], [], []
for pid, faces in particles.items():
    vidx = np.unique(np.concatenate(faces))
    c = pts[vidx].mean(axis=0)
    N, D = [], []
    vol = 0.0
    for f in faces:
        p = pts[f]
        n = np.cross(p[1] - p[0], p[2] - p[0])
        n /= np.linalg.norm(n)
        if np.dot(n, p[0] - c) < 0:
            n = -n
        N.append(n)
        D.append(np.dot(n, p[0]))
        # pyramid from the centre
        area = 0.5*np.linalg.norm(sum(np.cross(p[k], p[(k + 1) % len(p)]) for k in range(len(p))))
        vol += area*(np.dot(n, p[0]) - np.dot(n, c))/3
    planes.append((np.array(N), np.array(D)))
    centres.append(c)
    radii.append(np.max(np.linalg.norm(pts[vidx] - c, axis=1)))
    volumes.append(vol)
centres = np.array(centres)
radii = np.array(radii)

# Surface height: median over a 4 x 4 grid of the highest vertex
inBox = (pts[:, 0] > 0) & (pts[:, 0] < L) & (pts[:, 1] > 0) & (pts[:, 1] < L)
cell = (np.clip((pts[:, 0]/L*4).astype(int), 0, 3)*4 + np.clip((pts[:, 1]/L*4).astype(int), 0, 3))
tops = [pts[inBox & (cell == k), 2].max() for k in range(16) if np.any(inBox & (cell == k))]
hTop = float(np.median(tops))

rng = np.random.default_rng(1)
lo = np.array([2*a, 2*a, a])
hi = np.array([L - 2*a, L - 2*a, hTop - 2*a])
nMC = 200000
X = lo + (hi - lo)*rng.random((nMC, 3))
inside = np.zeros(nMC, dtype=bool)
for (Nn, Dd), c, r in zip(planes, centres, radii):
    near = np.where(np.sum((X - c)**2, axis=1) <= r*r)[0]
    if near.size:
        ok = np.all(X[near] @ Nn.T <= Dd + 1e-15, axis=1)
        inside[near[ok]] = True
phiBulk = inside.mean()
phiErr = np.sqrt(phiBulk*(1 - phiBulk)/nMC)
phiBed = sum(volumes)/(L*L*hTop)

# Coordination from the summary (last line)
summary = os.path.join(case, "postProcessing", "demFoam", "0", "summary.dat")
data = np.loadtxt(summary)
t, n, contacts, wallContacts, ke = data[:, 0], data[-1, 2], data[-1, 3], data[-1, 4], data[:, 6]
Z = 2*contacts/n
Zw = (2*contacts + wallContacts)/n

os.makedirs(os.path.join(case, "postProcessing"), exist_ok=True)
with open(os.path.join(case, "postProcessing", "packing.dat"), "w") as f:
    f.write("# time particles hTop[m] phiBulk phiBulkErr phiBed contacts wallContacts "
            "Z(particle-particle) Z(with walls) finalKineticEnergy[J]\n")
    f.write("%s %d %.5g %.4f %.4f %.4f %d %d %.3f %.3f %.3g\n"
            % (time, n, hTop, phiBulk, phiErr, phiBed, contacts, wallContacts, Z, Zw, ke[-1]))
print("t = %s s: %d cubes, bed height %.1f mm" % (time, n, 1e3*hTop))
print("packing fraction: bulk %.3f +- %.3f (Monte Carlo), whole bed %.3f" % (phiBulk, phiErr, phiBed))
print("coordination number: %.2f (particle-particle), %.2f (with walls); %d contacts, %d with walls"
      % (Z, Zw, contacts, wallContacts))
print("kinetic energy: max %.3g J, final %.3g J" % (ke.max(), ke[-1]))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.semilogy(t, data[:, 7], label="translational")
    ax.semilogy(t, data[:, 8], label="rotational")
    ax.semilogy(t, ke, "k", lw=1.5, label="total kinetic")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J]")
    ax.set_title("Cube stack: %d cubes settling (a batch of 50 every 0.15 s)" % n,
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, "postProcessing", "kineticEnergy.png"), dpi=130)
    print("wrote postProcessing/kineticEnergy.png")
except ImportError:
    print("no matplotlib: no plot")
