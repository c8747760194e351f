#!/usr/bin/env python3
"""Flow through the body: the flux that enters the cells whose centre is
inside the cube, over the frontal inflow U A_proj.

Reads the last time's mesh (<t>/polyMesh after the refinement, else
constant/polyMesh) and face flux phi (ascii or binary) with its own parser,
takes the cells whose centre lies inside the cube of constant/ibProperties
(position, size, rotation about z: the cells the kept forcing drives, centre
inside) and sums the flux of the internal faces between such a cell and a
cell outside:
    Q_in  = sum max(phi_in, 0),     phi_in: flux into the inside cell,
    leak  = Q_in/(U A_proj),   A_proj = a^2 (|cos angle| + |sin angle|),
    net   = sum phi_in/(U A_proj)    (mass balance of the inside: ~ 0).
A body-fitted wall has leak 0; with closedSurface true (directForcingIB 8.)
the faces carry the rigid (here zero) flux, so leak ~ 0 up to the solver
tolerance. U is the inlet value of 0/U (1 in makeCase.py).
-max m: exit status 1 when leak > m.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("-max", type=float, default=None)
ap.add_argument("-time", default=None, help="time folder (default: the latest)")
a = ap.parse_args()


def read_raw(path):
    data = open(path, "rb").read()
    m = re.search(rb"FoamFile\s*\{(.*?)\}", data, re.S)
    if not m:
        sys.exit("%s: no FoamFile header" % path)
    hdr = m.group(1).decode("latin-1")
    binary = re.search(r"format\s+binary", hdr) is not None
    lab = 4
    ma = re.search(r"label\s*=\s*(\d+)", hdr)
    if ma:
        lab = int(ma.group(1)) // 8
    return data, m.end(), binary, lab, hdr


def parse_list(data, pos, binary, dtype, ncomp):
    """A list 'N (...)' starting at or after pos: array (N, ncomp), end."""
    m = re.compile(rb"(\d+)\s*\(").search(data, pos)
    n = int(m.group(1))
    start = m.end()
    if binary:
        nbytes = n * ncomp * np.dtype(dtype).itemsize
        arr = np.frombuffer(data[start:start + nbytes], dtype=dtype).copy()
        end = start + nbytes + 1
    else:
        depth, i = 1, start
        while depth:
            c = data[i:i + 1]
            depth += (c == b"(") - (c == b")")
            i += 1
        txt = data[start:i - 1].decode().replace("(", " ").replace(")", " ")
        arr = np.array(txt.split(), dtype=dtype)
        end = i
    return arr.reshape(n, ncomp) if ncomp > 1 else arr, end


def read_labels(path):
    data, pos, binary, lab, _ = read_raw(path)
    return parse_list(data, pos, binary, np.int64 if lab == 8 else np.int32, 1)[0]


def read_points(path):
    data, pos, binary, _, _ = read_raw(path)
    return parse_list(data, pos, binary, np.float64, 3)[0]


def read_faces(path):
    data, pos, binary, lab, hdr = read_raw(path)
    dt = np.int64 if lab == 8 else np.int32
    if "faceCompactList" in hdr:
        offs, end = parse_list(data, pos, binary, dt, 1)
        labs, _ = parse_list(data, end, binary, dt, 1)
        return offs, labs
    # ascii faceList: N ( k(a b c ...) ... )
    m = re.compile(rb"(\d+)\s*\(").search(data, pos)
    body = data[m.end():].decode()
    offs, labs = [0], []
    for k, txt in re.findall(r"(\d+)\s*\(([^)]*)\)", body)[:int(m.group(1))]:
        v = [int(x) for x in txt.split()]
        labs.extend(v)
        offs.append(len(labs))
    return np.array(offs), np.array(labs)


def read_phi_internal(path):
    data, pos, binary, _, _ = read_raw(path)
    m = re.compile(rb"internalField\s+nonuniform\s+List<scalar>\s*").search(data, pos)
    if not m:
        sys.exit("%s: no nonuniform internalField" % path)
    return parse_list(data, m.end(), binary, np.float64, 1)[0]


times = [d for d in os.listdir(".") if re.fullmatch(r"[0-9.eE+-]+", d) and os.path.isdir(d)]
times = [d for d in times if float(d) > 0]
if a.time is None:
    if not times:
        sys.exit("no time folder > 0: run ./Allrun first")
    t = max(times, key=float)
else:
    t = a.time
meshDir = os.path.join(t, "polyMesh") if os.path.isfile(os.path.join(t, "polyMesh", "owner")) \
    else os.path.join("constant", "polyMesh")

pts = read_points(os.path.join(meshDir, "points"))
offs, labs = read_faces(os.path.join(meshDir, "faces"))
own = read_labels(os.path.join(meshDir, "owner"))
nei = read_labels(os.path.join(meshDir, "neighbour"))
phi = read_phi_internal(os.path.join(t, "phi"))
nInt = len(nei)
if len(phi) != nInt:
    sys.exit("phi has %d values, the mesh %d internal faces" % (len(phi), nInt))
nFaces = len(offs) - 1
nCells = int(max(own.max(), nei.max())) + 1

# Face centres (vertex mean) and cell centres (mean of the face centres):
# exact for the hexahedra near the cube, which is all that is classified
cnt = np.diff(offs)
fidx = np.repeat(np.arange(nFaces), cnt)
fc = np.zeros((nFaces, 3))
np.add.at(fc, fidx, pts[labs])
fc /= cnt[:, None]
cc = np.zeros((nCells, 3))
nf = np.zeros(nCells)
np.add.at(cc, own, fc[:len(own)])
np.add.at(nf, own, 1)
np.add.at(cc, nei, fc[:nInt])
np.add.at(nf, nei, 1)
cc /= nf[:, None]

ib = open("constant/ibProperties").read()
mp = re.search(r"position\s*\(\s*([-0-9.eE+]+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*\)", ib)
pos = np.array([float(x) for x in mp.groups()])
ms = re.search(r"size\s*\(\s*([-0-9.eE+]+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*\)", ib)
if not ms or "shape box" not in ib:
    sys.exit("checkLeak.py needs a box (shape box; size (...)) in constant/ibProperties")
size = np.array([float(x) for x in ms.groups()])
mr = re.search(r"angle\s+([-0-9.eE+]+)", ib)
ang = math.radians(float(mr.group(1))) if mr else 0.0
c, s = math.cos(ang), math.sin(ang)
r = cc - pos
xb = np.stack([c * r[:, 0] + s * r[:, 1], -s * r[:, 0] + c * r[:, 1], r[:, 2]], axis=1)
inside = np.all(np.abs(xb) < 0.5 * size, axis=1)

U = 1.0
mu = re.search(r"inlet\s*\{[^}]*value\s+uniform\s*\(\s*([-0-9.eE+]+)", open("0/U").read())
if mu:
    U = float(mu.group(1))
Aproj = size[1] * size[2] * (abs(c) + abs(s)) if size[0] == size[1] else size[1] * size[2]

o, n = own[:nInt], nei
surf = inside[o] != inside[n]
phiIn = np.where(inside[n], phi, -phi)[surf]   # into the inside cell
Qin = phiIn[phiIn > 0].sum()
net = phiIn.sum()
print("time %s: %d cells inside, %d surface faces; inflow into the body Q_in = %.4g "
      "= %.2f %% of U A_proj (A_proj %.4g); net %.2e U A_proj"
      % (t, inside.sum(), surf.sum(), Qin, 100 * Qin / (U * Aproj), Aproj, net / (U * Aproj)))
leak = Qin / (U * Aproj)
if a.max is not None:
    ok = leak <= a.max
    print("%s: leak %.3f %% %s %.3f %%" % ("PASS" if ok else "FAIL", 100 * leak,
                                          "<=" if ok else ">", 100 * a.max))
    sys.exit(0 if ok else 1)
