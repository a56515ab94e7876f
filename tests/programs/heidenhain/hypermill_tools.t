BEGIN TOOL.T MM
T    NAME             L           R           R2          DL      DR      DR2     TL RT
0    NULLWERKZEUG     +0          +0          +0          +0      +0      +0
10   EM10             +75         +5          +0          +0      +0      +0
[END]
