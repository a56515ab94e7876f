#pragma once
// G and M functions of the Sinumerik dialect by name, held as their number (G450 is 450).
// The interpreter compares functions by these names only.

namespace toolcomp::sinumerik {

enum GCode : int {
    G0 = 0, G1 = 1, G2 = 2, G3 = 3, G4 = 4, G9 = 9, G17 = 17, G18 = 18, G19 = 19, G25 = 25, G26 = 26,
    G40 = 40, G41 = 41, G42 = 42, G53 = 53, G54 = 54, G55 = 55, G56 = 56, G57 = 57, G58 = 58, G59 = 59,
    G60 = 60, G64 = 64, G70 = 70, G71 = 71, G90 = 90, G91 = 91, G94 = 94, G95 = 95, G96 = 96, G97 = 97,
    G110 = 110, G111 = 111, G112 = 112, G153 = 153, G450 = 450, G451 = 451, G500 = 500, G505 = 505,
    G599 = 599, G601 = 601, G602 = 602, G603 = 603, G641 = 641, G642 = 642, G643 = 643, G644 = 644,
    G645 = 645, G700 = 700, G710 = 710,
};

// The circles through a point (CIP) and tangential (CT) have no G number: the motion mode
// holds them beside G0-G3 as 5 and 6.
enum CircleMode : int { CIP = 5, CT = 6 };

enum MCode : int { M0 = 0, M1 = 1, M2 = 2, M6 = 6, M17 = 17, M30 = 30 };

}  // namespace toolcomp::sinumerik
