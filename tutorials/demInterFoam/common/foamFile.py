"""The one writer of OpenFOAM dictionaries and fields for the demInterFoam
tutorials' makeCase.py scripts: the C++-mode banner naming the tutorial, the
FoamFile header, the body, OpenFOAM's closing line."""
import os

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  {banner}
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    object      {obj};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""
FOOTER = "\n// ************************************************************************* //\n"


def write(path, obj, body, banner, cls="dictionary"):
    """Write path (its folder made if needed): banner (one line, e.g.
    'Hedra tutorial: floatingBlocks (demInterFoam), written by makeCase.py'),
    the FoamFile header of class cls and object obj, body."""
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER.format(banner=banner, cls=cls, obj=obj) + body + FOOTER)
