(Full circle in the ZX plane, G18: the plane is Z then X, seen from +Y)
(Arcs need the same steps per mm on Z and X.)
G21 G90 G18
G0 X10 Y0 Z0
G2 X10 Z0 I-10 K0 F400
G1 X0 Z10
G2 X10 Z0 I0 K-10 (quarter: from Z10 clockwise to X10)
