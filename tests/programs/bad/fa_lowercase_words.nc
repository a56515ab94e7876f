g21 g90 g17
g0 x0 y0 z5
g1 z-1 f100
g1 x10
g1 y10
g0 z5
m30
