"""Hedra's ship-in-brash-ice tools (python3, numpy, matplotlib).

foamDict  -- OpenFOAM dictionary reader with FatalIOError-style messages
convex    -- convex prisms (ice blocks), exact separating-axis overlap test
channel   -- the brash-ice channel builder (brashIceChannel)
hull      -- parametric ice-going bow and the seed report's dummy hull (iceHull)
mesh      -- blockMesh / snappyHexMesh set-up around a hull STL
fsicr     -- Finnish-Swedish Ice Class Rules channel resistance R_CH (fsicr)
case      -- makeBrashIceCase(): one call that writes all of the above into a case
"""
