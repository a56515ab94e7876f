BEGIN PGM X MM
1    MILL_10          +95.25      +5          +0          +0      -0.02   +0      
2    DRILL_6          +80.5       +3          +0          +0      +0      +0      
[END]
