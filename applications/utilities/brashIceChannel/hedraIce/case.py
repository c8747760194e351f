"""makeBrashIceCase: the seed report's ship-in-brash-ice set-up, written into a case.

    import sys; sys.path.insert(0, "$HEDRA_DIR/applications/utilities/brashIceChannel")
    from hedraIce.case import makeBrashIceCase
    info = makeBrashIceCase("myCase", full=False)

writes, and returns the numbers of:
  system/iceHullDict + constant/triSurface/hull.stl   the hull (default: the
        seed report's dummy hull, bow towards -x, stem at `stemX`, waterline at
        `waterLevel`); the same STL is the DEM wall (walls { hull { type mesh;
        file "hull.stl"; ... } }) and the snappyHexMesh surface
  system/brashIceChannelDict + constant/brashIce/{materials,particleTypes,insertion}
        the ice from the inlet (plus `iceGap`) to `iceGap` before the stem
  system/iceChannelMeshDict + blockMeshDict, snappyHexMeshDict,
        surfaceFeatureExtractDict (mesh: surfaceFeatureExtract; blockMesh;
        snappyHexMesh -overwrite)
  postProcessing/fsicr/fsicr.dat   the FSICR rule channel resistance of the
        hull at full scale (x `scale`) and / scale^3, channel thickness H_M =
        the model ice thickness x scale (a rule formula, not a validation)
It does not write the solver dictionaries (controlDict, fvSchemes, fields,
couplingProperties, the rest of demProperties): those belong to the tutorial.

Seed report (full=True): domain 10 m x 2 m, 2.5 m water + 2.5 m air, cells
0.02 m, ice blocks 0.1 m, ice 0.1 m thick, rho_ice 920, rho_water 1010,
E 2e9 Pa, nu 0.3, scale 1:100.  Reduced (full=False, the default): domain
4 m x 1 m x (0.6 m water + 0.4 m air), cells 0.04 m -- shorter and narrower so
that the ice field (~150 blocks) and the mesh (~10^5 cells) fit a 2-core run;
the hull, the blocks and the ice thickness are the report's.  The report gives
no porosity: 0.35 here (typical of brash-ice channels; packing lattice,
which reaches it -- random addition jams near 0.45; see docs/brashIce.md).
"""
import os

from . import channel as _channel
from . import hull as _hull
from . import mesh as _mesh
from . import fsicr as _fsicr
from .foamDict import Dict


def makeBrashIceCase(case, full=False, porosity=0.35, packing="lattice", seed=1, blockSize=0.1,
                     iceThickness=0.1, sizeDistribution=None, shape="cuboid",
                     stemX=None, iceGap=0.05, scale=100.0, iceClass="IA",
                     hullDict="type dummy;", cellSize=None, domain=None, velocity=None,
                     snap=True, bowPoints=96, hullLevels=8):
    if domain is not None:
        (dmin, dmax, zw), cell = domain, 0.04
        if stemX is None:
            raise ValueError("makeBrashIceCase: with 'domain', give 'stemX' too")
    elif full:
        dmin, dmax, zw, cell = (0.0, -1.0, 0.0), (10.0, 1.0, 5.0), 2.5, 0.02
        stemX = 3.0 if stemX is None else stemX
    else:
        dmin, dmax, zw, cell = (0.0, -0.5, 0.0), (4.0, 0.5, 1.0), 0.6, 0.04
        stemX = 2.2 if stemX is None else stemX
    cell = cellSize or cell
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    # hull
    with open(os.path.join(case, "system", "iceHullDict"), "w") as f:
        f.write("// makeBrashIceCase: the hull, its placement and the FSICR input\n"
                f"hull {{ {hullDict} }}\n"
                f"placement {{ stem ({stemX} 0 {zw}); bowDirection -x; }}\n"
                f"resolution {{ bowPoints {bowPoints}; levels {hullLevels}; }}\n"
                f"fsicr {{ scale {scale}; iceClass {iceClass}; "
                f"channelThickness {iceThickness * scale}; }}\n")
    _hull.main(["-case", case])
    # ice
    sd = sizeDistribution or (f"type uniform; min {0.8 * blockSize}; max {1.2 * blockSize};")
    x0 = dmin[0] + iceGap
    length = stemX - iceGap - x0
    shape_entry = {"cuboid": "type cuboid;", "sphere": "type sphere;",
                   "plate": "type plate; corners 7; elongation 0.7; shapes 3;"}[shape]
    with open(os.path.join(case, "system", "brashIceChannelDict"), "w") as f:
        f.write("// makeBrashIceCase: the brash-ice channel ahead of the hull\n"
                f"channel {{ origin ({x0} {dmin[1] + iceGap}); length {length}; "
                f"width {dmax[1] - dmin[1] - 2 * iceGap}; waterLevel {zw}; }}\n"
                f"thickness {{ type uniform; value {iceThickness}; }}\n"
                f"blockThickness {iceThickness};\n"
                f"sizeDistribution {{ {sd} }}\n"
                "sizeClasses 4;\n"
                f"shape {{ {shape_entry} }}\n"
                f"porosity {porosity};\nseed {seed};\npacking {packing};\n"
                "iceDensity 920;\nwaterDensity 1010;\n"
                + ("" if velocity is None else
                   f"velocity ({velocity[0]} {velocity[1]} {velocity[2]});\n") +
                "iceMaterial { youngsModulus 2e9; poissonsRatio 0.3; }\n")
    ch = _channel.Channel(os.path.join(case, "system", "brashIceChannelDict"))
    ch.build()
    summary = ch.write(case)
    # mesh set-up
    with open(os.path.join(case, "system", "iceChannelMeshDict"), "w") as f:
        f.write(f"domain {{ min ({dmin[0]} {dmin[1]} {dmin[2]}); "
                f"max ({dmax[0]} {dmax[1]} {dmax[2]}); }}\n"
                f"cellSize {cell};\nwaterLevel {zw};\nhullLevel 1;\nfreeSurfaceLevel 1;\n"
                f"snap {'true' if snap else 'false'};\n")
    _mesh.main(["-case", case])
    _fsicr.main(["-case", case])
    fs = {}
    with open(os.path.join(case, "postProcessing", "fsicr", "fsicr.dat")) as f:
        for line in f:
            if not line.startswith("#"):
                k, v = line.split()
                fs[k] = float(v)
    h = _hull.hull_from_dict(Dict.read(os.path.join(case, "system", "iceHullDict")).sub("hull"))
    return dict(case=case, domainMin=dmin, domainMax=dmax, waterLevel=zw, cellSize=cell,
                stemX=stemX, hullVolume=h.volume(), hullBeam=h.B, hullLength=h.L,
                ice=summary, fsicr=fs)
