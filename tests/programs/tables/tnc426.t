BEGIN TOOL .T MM
T    NAME             L           R           R2          DL      DR      DR2     LCUTS   ANGLE   TL RT  TIME1 TIME2 CUR.TIME DOC              PLC       CUT LTOL    RTOL    DIRECT TT:R-OFFS TT:L-OFFS LBREAK  RBREAK  COOLANT 
0    NULLWERKZEUG     +0          +0          +0          +0      +0      +0      +0      +0             0     0     0                         %00000000 0   +0      +0      -1     R         +0        +0      +0              
1    SCHAFTFRAESER_10 +95.25      +5          +0          +0      -0.02   +0      +20     +0             240   0     37       SCHRUPPEN Z4     %00000001 4   +0.1    +0.05   -1     R         +0        +0.2    +0.05   AUSSEN  
2    KUGELFRAESER_6   +80.5       +3          +3          +0      +0      +0.01   +12     +0             120   0     0        SCHLICHTEN 3D    %00000000 2   +0.1    +0.05   -1     0         +3        +0.2    +0.05   INNEN   
3    TORUSFRAESER_16  +110.3      +8          +1.5        +0.05   -0.015  +0      +25     +30            0     0     0        TORUS R1.5       %00000000 4   +0      +0      -1     R         +0        +0      +0              
5    BOHRER D8,5      +120.125    +4.25       +0          +0      +0      +0      +60     +0             0     0     12                        %00000000 0   +0      +0      -1     R         +0        +0      +0      INNEN   
7    FASE_90                                                                                      L  8   0     0     0        GESPERRT         %00000000                                                                        
12   FRÄSER_D20       +150        +10         +0          -0.1    +0      +0      +40     +0             0     0     0        Ø20 HM           %00000000 6   +0      +0      -1     R         +0        +0      +0              
[END]
