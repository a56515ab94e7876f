BEGIN TOOL.T MM
T    NAME             L           R           R2          DL      DR      DR2     TL RT
0    NULLWERKZEUG     +0          +0          +0          +0      +0      +0
3    CENTER6          +80         +3          +0          +0      +0      +0
4    EM8              +90         +4          +0          +0      +0      +0
[END]
