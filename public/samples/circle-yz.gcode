(Full circle in the YZ plane, G19, seen from +X)
(Arcs need the same steps per mm on Y and Z.)
G21 G90 G19
G0 X0 Y10 Z0
G3 Y10 Z0 J-10 K0 F400
