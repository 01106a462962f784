(Spiral of arcs: half circles about alternating centers, radius +2.5 mm per half turn)
G21 G90 G17
G0 X0 Y0
G3 X10 Y0 I5 J0 F500
G3 X-5 Y0 I-7.5 J0
G3 X15 Y0 I10 J0
G3 X-10 Y0 I-12.5 J0
G3 X20 Y0 I15 J0
G3 X-15 Y0 I-17.5 J0
G3 X25 Y0 I20 J0
G3 X-20 Y0 I-22.5 J0
