(R-format arcs: R > 0 takes the arc of at most 180 degrees, R < 0 the longer one)
G21 G90 G17
G0 X0 Y0
G2 X8 Y0 R5 F400 (short way: 106 degrees, over the top at Y2)
G0 X0 Y0
G2 X8 Y0 R-5 (long way: 254 degrees, round through X-1, Y8 and X9)
