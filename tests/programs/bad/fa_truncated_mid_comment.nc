G21 G90 G17
G0 X0 Y0 Z5
G1 Z-1 F100 (start of the con