(A 20 mm square, absolute coordinates)
G21 G90 G17
G0 X0 Y0 Z0
G1 X20 Y0 F500
Y20
X0
Y0
