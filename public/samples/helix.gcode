(Helix: three turns of r = 10 mm while Z goes down 6 mm; P3 = three turns)
G21 G90 G17
G0 X10 Y0 Z0
G2 X10 Y0 Z-6 I-10 J0 P3 F300
G0 Z0
