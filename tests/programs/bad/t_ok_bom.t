BEGIN TOOL .T MM
T    NAME             L           R           R2          DL      DR      DR2     
1    MILL_10          +95.25      +5          +0          +0      -0.02   +0      
2    DRILL_6          +80.5       +3          +0          +0      +0      +0      
[END]
