"""LIGGGHTS back end helpers for the validation scripts: a LIGGGHTS input
script that sets up the same DEM as hedracase.dem_properties (Hertz-Mindlin
spheres, plane walls, gravity), and the couplingProperties lines that select
it (demBackend liggghts)."""
import os


def script(case, box, dt, density, diameter, positions, floor_z=None,
           E=5e6, restitution=0.5, friction=0.5, g=9.81, coupling=True,
           extra="", name="in.liggghts", restart=False, couple_every=1):
    """constant/liggghts/<name>: one atom type, spheres at positions
    (ids 1.. in that order), at rest; restart: the same set-up read from
    ${restartFile} (the back end's restartScript). couple_every: with the
    mpi data coupling only how often couple/cfd prints 'CFD Coupling
    established' (give the DEM steps per fluid step)."""
    (x0, y0, z0), (x1, y1, z1) = box
    atoms = "\n".join(f"create_atoms 1 single {x} {y} {z} units box"
                      for x, y, z in positions)
    walls = (f"fix floor all wall/gran model hertz tangential history"
             f" primitive type 1 zplane {floor_z}\n" if floor_z is not None else "")
    couple = (f"fix cfd all couple/cfd couple_every {couple_every} mpi\n"
              "fix cfd2 all couple/cfd/force\n" if coupling else "")
    if restart:
        setup = "read_restart ${restartFile}\n"
        atoms = ""
        sizes = ""
    else:
        setup = (f"boundary f f f\nunits si\nprocessors * * *\n"
                 f"region domain block {x0} {x1} {y0} {y1} {z0} {z1} units box\n"
                 f"create_box 1 domain\n")
        sizes = f"set group all diameter {diameter} density {density}\n"
    txt = f"""# LIGGGHTS input (Hedra test): the DEM of the polyDEM run
atom_style granular
atom_modify map array
communicate single vel yes
newton off
{setup}neighbor {0.5 * diameter} bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {E}
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 {restitution}
fix m4 all property/global coefficientFriction peratomtypepair 1 {friction}
pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt}
fix gravi all gravity {g} vector 0.0 0.0 -1.0
{walls}{atoms}
{sizes}{couple}fix integr all nve/sphere
{extra}"""
    path = os.path.join(case, "constant", "liggghts", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(txt)
    return path


def coupling_lines(script="constant/liggghts/in.liggghts", restart=None):
    r = f'    restartScript "{restart}";\n' if restart else ""
    return (f'demBackend liggghts;\nliggghtsCoeffs\n{{\n'
            f'    inputScript "{script}";\n{r}}}\n')
