"""iceChannelMesh: blockMesh + snappyHexMesh set-up of a channel around a hull STL.

Writes system/blockMeshDict (the channel box, uniform cells of `cellSize`,
patches inlet (x min), outlet (x max), sides (y), bottom, atmosphere (top)),
system/surfaceFeatureExtractDict, system/snappyHexMeshDict (surface `hull`
refined to `hullLevel`, a distance band of `hullDistance` around it, a box
`freeSurface` of +-`freeSurfaceBand` about the water level refined to
`freeSurfaceLevel`; snapped to the hull's feature edges; no layers) and, when
absent, the minimal controlDict / fvSchemes / fvSolution the mesh tools read.
The STL is constant/triSurface/hull.stl: the same file is the DEM `mesh` wall
(docs/demProperties.md, walls type mesh), so fluid and ice see one hull.
Run:  surfaceFeatureExtract; blockMesh; snappyHexMesh -overwrite; checkMesh
"""
import math
import os

from .foamDict import Dict, header

KEYS = ["domain", "cellSize", "waterLevel", "freeSurfaceBand", "freeSurfaceLevel",
        "hullLevel", "hullDistance", "locationInMesh", "hullFile", "snap"]


def write_mesh_setup(case, dmin, dmax, cell, water_level, band=None, fs_level=1,
                     hull_level=2, hull_distance=None, location=None, hull_file="hull.stl",
                     snap=True):
    sysd = os.path.join(case, "system")
    os.makedirs(sysd, exist_ok=True)
    n = [max(1, int(round((dmax[i] - dmin[i]) / cell))) for i in range(3)]
    band = 2 * cell if band is None else band
    hull_distance = 2 * cell if hull_distance is None else hull_distance
    if location is None:  # in the water, a tenth of the domain from the inlet
        location = [dmin[0] + 0.1 * (dmax[0] - dmin[0]) + 0.013 * cell,
                    dmin[1] + 0.5 * (dmax[1] - dmin[1]) + 0.017 * cell,
                    0.5 * (dmin[2] + water_level) + 0.011 * cell]
    x0, y0, z0 = dmin
    x1, y1, z1 = dmax
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    with open(os.path.join(sysd, "blockMeshDict"), "w") as f:
        f.write(header("dictionary", "blockMeshDict", "system"))
        f.write("// iceChannelMesh: the channel, uniform cells of %g m\n" % cell)
        f.write("scale 1;\nvertices\n(\n" + "".join(
            f"    ({a:.12g} {b:.12g} {c:.12g})\n" for a, b, c in v) + ");\n")
        f.write(f"blocks\n(\n    hex (0 1 2 3 4 5 6 7) ({n[0]} {n[1]} {n[2]}) simpleGrading (1 1 1)\n);\n")
        f.write("edges ();\nboundary\n(\n"
                "    inlet      { type patch; faces ((0 4 7 3)); }\n"
                "    outlet     { type patch; faces ((1 2 6 5)); }\n"
                "    sides      { type wall;  faces ((0 1 5 4) (3 7 6 2)); }\n"
                "    bottom     { type wall;  faces ((0 3 2 1)); }\n"
                "    atmosphere { type patch; faces ((4 5 6 7)); }\n);\n")
    with open(os.path.join(sysd, "surfaceFeatureExtractDict"), "w") as f:
        f.write(header("dictionary", "surfaceFeatureExtractDict", "system"))
        f.write(f"{hull_file}\n{{\n    extractionMethod extractFromSurface;\n"
                "    extractFromSurfaceCoeffs { includedAngle 150; }\n"
                "    subsetFeatures { nonManifoldEdges no; openEdges yes; }\n"
                "    writeObj no;\n}\n")
    emesh = os.path.splitext(hull_file)[0] + ".eMesh"
    big = 10 * max(x1 - x0, y1 - y0, z1 - z0)
    with open(os.path.join(sysd, "snappyHexMeshDict"), "w") as f:
        f.write(header("dictionary", "snappyHexMeshDict", "system"))
        f.write(f"""// iceChannelMesh: hull patch `hull`, refined near the hull and at the free surface
castellatedMesh true;
snap            {"true" if snap else "false"};
addLayers       false;

geometry
{{
    hull
    {{
        type triSurfaceMesh;
        file "{hull_file}";
    }}
    freeSurface
    {{
        type searchableBox;
        min ({x0 - big:.12g} {y0 - big:.12g} {water_level - band:.12g});
        max ({x1 + big:.12g} {y1 + big:.12g} {water_level + band:.12g});
    }}
}}

castellatedMeshControls
{{
    maxLocalCells       2000000;
    maxGlobalCells      20000000;
    minRefinementCells  0;
    maxLoadUnbalance    0.10;
    nCellsBetweenLevels 2;
    features ( {{ file "{emesh}"; level {hull_level}; }} );
    refinementSurfaces
    {{
        hull
        {{
            level ({hull_level} {hull_level});
            patchInfo {{ type wall; }}
        }}
    }}
    resolveFeatureAngle 30;
    refinementRegions
    {{
        freeSurface {{ mode inside; levels ((1e15 {fs_level})); }}
        hull {{ mode distance; levels (({hull_distance:.12g} {hull_level})); }}
    }}
    locationInMesh ({location[0]:.12g} {location[1]:.12g} {location[2]:.12g});
    allowFreeStandingZoneFaces true;
}}

snapControls
{{
    nSmoothPatch        3;
    tolerance           2.0;
    nSolveIter          50;
    nRelaxIter          5;
    nFeatureSnapIter    10;
    implicitFeatureSnap false;
    explicitFeatureSnap true;
    multiRegionFeatureSnap false;
}}

addLayersControls
{{
    relativeSizes true;
    layers {{ }}
    expansionRatio 1.0;
    finalLayerThickness 0.3;
    minThickness 0.1;
    nGrow 0;
    featureAngle 60;
    nRelaxIter 3;
    nSmoothSurfaceNormals 1;
    nSmoothNormals 3;
    nSmoothThickness 10;
    maxFaceThicknessRatio 0.5;
    maxThicknessToMedialRatio 0.3;
    minMedialAxisAngle 90;
    nBufferCellsNoExtrude 0;
    nLayerIter 50;
}}

meshQualityControls
{{
    maxNonOrtho 65;
    maxBoundarySkewness 20;
    maxInternalSkewness 4;
    maxConcave 80;
    minVol 1e-13;
    minTetQuality 1e-15;
    minArea -1;
    minTwist 0.02;
    minDeterminant 0.001;
    minFaceWeight 0.05;
    minVolRatio 0.01;
    minTriangleTwist -1;
    nSmoothScale 4;
    errorReduction 0.75;
    relaxed {{ maxNonOrtho 75; }}
}}

mergeTolerance 1e-6;
""")
    for name, body in _minimal().items():
        p = os.path.join(sysd, name)
        if not os.path.exists(p):
            with open(p, "w") as f:
                f.write(header("dictionary", name, "system") + body)
    return n


def _minimal():
    return {
        "controlDict": "application snappyHexMesh;\nstartFrom startTime;\nstartTime 0;\n"
                       "stopAt endTime;\nendTime 1;\ndeltaT 1;\nwriteControl timeStep;\n"
                       "writeInterval 1;\nwriteFormat ascii;\nwritePrecision 10;\n"
                       "timePrecision 6;\nrunTimeModifiable false;\n",
        "fvSchemes": "ddtSchemes { default Euler; }\ngradSchemes { default Gauss linear; }\n"
                     "divSchemes { default none; }\nlaplacianSchemes { default Gauss linear corrected; }\n"
                     "interpolationSchemes { default linear; }\nsnGradSchemes { default corrected; }\n",
        "fvSolution": "solvers { }\n",
    }


def main(argv=None):
    import argparse
    p = argparse.ArgumentParser(description="Write the blockMesh/snappyHexMesh set-up of "
                                "a brash-ice channel around constant/triSurface/hull.stl")
    p.add_argument("-case", default=".")
    p.add_argument("-dict", default="system/iceChannelMeshDict")
    a = p.parse_args(argv)
    dfile = a.dict if os.path.isabs(a.dict) else os.path.join(a.case, a.dict)
    d = Dict.read(dfile)
    d.check_keys(KEYS)
    dom = d.sub("domain")
    dom.check_keys(["min", "max"])
    dmin, dmax = dom.get("min", "vector"), dom.get("max", "vector")
    for i, c in enumerate("xyz"):
        if dmax[i] <= dmin[i]:
            dom.error("max", f"max {c} must be more than min {c}")
    cell = d.get("cellSize", float, min=0, strict_min=True)
    zw = d.get("waterLevel", float)
    if not dmin[2] < zw < dmax[2]:
        d.error("waterLevel", f"waterLevel {zw} is not inside the domain ({dmin[2]}, {dmax[2]})")
    n = write_mesh_setup(
        a.case, dmin, dmax, cell, zw,
        band=d.get("freeSurfaceBand", float, default=2 * cell, min=0, strict_min=True),
        fs_level=d.get("freeSurfaceLevel", int, default=1, min=0, max=6),
        hull_level=d.get("hullLevel", int, default=2, min=0, max=8),
        hull_distance=d.get("hullDistance", float, default=2 * cell, min=0),
        location=d.get("locationInMesh", "vector") if "locationInMesh" in d else None,
        hull_file=d.get("hullFile", str, default="hull.stl"),
        snap=d.get("snap", bool, default=True))
    print(f"iceChannelMesh: blockMesh {n[0]} x {n[1]} x {n[2]} cells of {cell} m; "
          "wrote system/{blockMeshDict,surfaceFeatureExtractDict,snappyHexMeshDict}")
    return 0
