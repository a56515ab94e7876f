#pragma once
// SETTCOR: write tool length / radius corrections into a Sinumerik edge (spec §3.5).
//
//   Status = SETTCOR(_CORVAL, _COMP, _CORCOMP, _CORMODE, _GEOAX, _T, _D, _DL)
//
// _COMP: one or two component letters from G (geometry DP3..5 / DP6), W (wear DP12..14 /
// DP15), E (setup ECP), S (sum SCP), C (adapter DP21..23; no radius), optionally ":W" (values
// as measured in the workpiece system, default) or ":T" (tool system). Only the first
// component is written. _CORCOMP: 0 the scalar _CORVAL[0] along geometry axis _GEOAX
// (1 X, 2 Y, 3 Z) of the WCS, 1 the vector _CORVAL in the WCS, 2 the vector in tool
// coordinates, 3..5 L1..L3 directly by _CORVAL[0], 6 the radius by _CORVAL[0].
// WCS values reach L1..L3 through the §3.2 axis tables of the active plane. No frames or
// toolholders are modelled, so the tool system has the workpiece system's axes (2 == 1).
// Choices [U]: _CORMODE 0 replaces (with two letters the first component becomes the value
// less the second, so that their sum is the value), 1 adds; _GEOAX counts from 1. The wear
// sign (SD42930) is not applied to written values. `edge` is only changed when the status
// is 0.
#include <string_view>

#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/tools/sinumerik_gettcor.hpp"

namespace toolcomp::sinumerik {

enum SettcorStatus : int {
    settcor_bad_corcomp = -10,  // _CORCOMP outside 0..6
    settcor_bad_cormode = -11,  // _CORMODE not 0 or 1
    settcor_bad_geoax = -12,    // _GEOAX outside 1..3 (with _CORCOMP 0)
    settcor_no_radius = -13,    // _CORCOMP 6 on component C (adapter dimensions have no radius)
};

// Status 0 on success; -3 (_COMP invalid), -9 (bad coordinate-system letter) as GETTCOR, or
// the SettcorStatus values.
int settcor(SinumerikEdge& edge, const Vec3& corval, std::string_view comp, int corcomp, int cormode, int geoax,
            Plane plane, const SinumerikLengthSettings& s = {});

// The same on edge (t, d) of a table: -4 when tool t has no edge, -5 when it lacks edge d.
int settcor(SinumerikEdgeMap& edges, int t, int d, const Vec3& corval, std::string_view comp, int corcomp,
            int cormode, int geoax, Plane plane, const SinumerikLengthSettings& s = {});

}  // namespace toolcomp::sinumerik
