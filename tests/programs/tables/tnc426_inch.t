BEGIN TOOL .T INCH
T    NAME             L           R           R2          DL       DR       DR2      TL RT  DOC              PLC      
1    ENDMILL_1/2      +3.75       +0.25       +0          +0       -0.0005  +0              HALF INCH        %00000000
2    BALL_1/4         +2.5        +0.125      +0.125      +0       +0       +0                               %00000000
3    BULL_3/4         +4          +0.375      +0.0625     +0.002   +0       -0.001          R1/16            %00000000
[END]
