"""A drum's fluid mesh turning with its shell as a solid body, for
demInterFoam (the wet ball mill, tutorials/demInterFoam/wetBallMill, and
the tests through tests/validation/vofcase.py: drum_mesh, rotating_mesh):

  o_grid_block_mesh  blockMeshDict body of an O-grid of a circle of radius R
                     about the z axis (an inner square of half side C with
                     N x N cells, four blocks of N x M cells out to the
                     circle), one cell thick (z0 .. z1); patches: 'shell'
                     (wall) and the two ends (one patch, type sides)
  dynamic_mesh_dict  constant/dynamicMeshDict body: the whole mesh turns
                     about the z axis through the origin at omega [rad/s]
                     (dynamicMotionSolverFvMesh, solidBody, rotatingMotion;
                     right-handed: omega > 0 is counter-clockwise seen
                     from +z)
  PIMPLE_O_GRID      the PIMPLE entries this mesh needs: with interFoam's
                     default velocity correction (reconstruct) the solver
                     diverges from rest on this O-grid, as interFoam itself
                     does, within 6 steps; gradient is stable but breaks
                     the balance of pressure and gravity at a free surface;
                     gaussBalance keeps it (docs/models.md, "Velocity
                     correction"); correctPhi after the mesh motion, and
                     the motion once per time step
  shell_polygon      the mesh's cross-section (the shell's faces are chords
                     between points equally spaced on the circle)

Plain python3; the tutorials' and tests' own writers add the file headers.
"""
import math

PIMPLE_O_GRID = """    correctPhi yes;
    moveMeshOuterCorrectors no;
    velocityCorrection gaussBalance;
"""


def o_grid_block_mesh(R, N, M, C, z0, z1, sides="frontAndBack", sideType="empty"):
    a = R / math.sqrt(2)
    pts = [(-C, -C), (C, -C), (C, C), (-C, C), (-a, -a), (a, -a), (a, a), (-a, a)]
    verts = " ".join(f"({x:.12g} {y:.12g} {z0:.12g})" for x, y in pts) + " " + \
        " ".join(f"({x:.12g} {y:.12g} {z1:.12g})" for x, y in pts)
    arcs = ""
    for (i, j), (mx, my) in {(4, 5): (0, -R), (5, 6): (R, 0), (6, 7): (0, R), (7, 4): (-R, 0)}.items():
        arcs += (f"    arc {i} {j} ({mx:.12g} {my:.12g} {z0:.12g})\n"
                 f"    arc {i + 8} {j + 8} ({mx:.12g} {my:.12g} {z1:.12g})\n")
    return f"""
convertToMeters 1;
vertices ( {verts} );
blocks
(
    hex (0 1 2 3 8 9 10 11) ({N} {N} 1) simpleGrading (1 1 1)
    hex (4 5 1 0 12 13 9 8) ({N} {M} 1) simpleGrading (1 1 1)
    hex (5 6 2 1 13 14 10 9) ({N} {M} 1) simpleGrading (1 1 1)
    hex (6 7 3 2 14 15 11 10) ({N} {M} 1) simpleGrading (1 1 1)
    hex (7 4 0 3 15 12 8 11) ({N} {M} 1) simpleGrading (1 1 1)
);
edges
(
{arcs});
boundary
(
    shell {{ type wall; faces ((4 5 13 12) (5 6 14 13) (6 7 15 14) (7 4 12 15)); }}
    {sides}
    {{
        type {sideType};
        faces
        (
            (0 3 2 1) (4 0 1 5) (5 1 2 6) (6 2 3 7) (7 3 0 4)
            (8 9 10 11) (12 13 9 8) (13 14 10 9) (14 15 11 10) (15 12 8 11)
        );
    }}
);
"""


def dynamic_mesh_dict(omega):
    return f"""
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolver    solidBody;
solidBodyMotionFunction rotatingMotion;
origin  (0 0 0);
axis    (0 0 1);
omega   {omega:.12g};
"""


def shell_polygon(R, N):
    """The O-grid's boundary points, counter-clockwise: 4 N points on the
    circle, equally spaced in angle from -135 deg (blockMesh's arcs with
    uniform grading)."""
    return [(R * math.cos(math.radians(-135 + 90 * k / N)),
             R * math.sin(math.radians(-135 + 90 * k / N))) for k in range(4 * N)]


def polygon_area_below(poly, level):
    """Area of the polygon (counter-clockwise) below the line y = level."""
    out = []
    n = len(poly)
    for k in range(n):
        (xa, ya), (xb, yb) = poly[k], poly[(k + 1) % n]
        ina, inb = ya <= level, yb <= level
        if ina:
            out.append((xa, ya))
        if ina != inb:
            t = (level - ya) / (yb - ya)
            out.append((xa + t * (xb - xa), level))
    a = 0.0
    for k in range(len(out)):
        x0, y0 = out[k]
        x1, y1 = out[(k + 1) % len(out)]
        a += x0 * y1 - x1 * y0
    return 0.5 * a


def level_for_area(poly, area):
    """The level y below which the polygon holds 'area' (bisection)."""
    lo = min(p[1] for p in poly)
    hi = max(p[1] for p in poly)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if polygon_area_below(poly, mid) < area:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
