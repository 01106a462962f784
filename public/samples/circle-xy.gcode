(Full circle in the XY plane, G17: end = start with I J)
G21 G90 G17
G0 X10 Y0
G2 X10 Y0 I-10 J0 F400 (clockwise, seen from +Z)
G3 X10 Y0 I-10 J0 (and back, counter-clockwise)
