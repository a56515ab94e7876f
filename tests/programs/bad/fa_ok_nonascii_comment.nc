(Fräser Ø6 – Tiefe ≤ 1 mm, 日本語)
G21 G90 G17
G0 X0 Y0 Z5
G1 Z-1 F100
G1 X10
G1 Y10
G0 Z5
M30
