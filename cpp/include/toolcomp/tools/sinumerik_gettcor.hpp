#pragma once
// GETTCOR: read tool length components of a Sinumerik edge (spec §3.5).
//
//   Status = GETTCOR(_LEN, _COMP, _STAT, _T, _D, _DL)
//
// _LEN[0] tool type (DP1), [1] cutting-edge position (DP2), [2] abscissa, [3] ordinate,
// [4] applicate length of the active plane (G17: X Y Z, G18: Z X Y, G19: Y Z X), [5] radius,
// [6]..[10] the additional values (G: DP7..DP11, W: DP16..DP20, S/E: SCP/ECP16..20).
// [0] and [1] are always set; [2]..[4] are the sum of the chosen components, each placed on
// the axes with the §3.2 tables; [5]..[10] get values from E, G, S, W only (C adds lengths).
//
// Components (case and white space ignored, each letter at most once): G geometry
// DP3..5, W wear DP12..14, E setup offsets ECP12..14, S sum offsets SCP12..14, C adapter /
// base dimension DP21..23. Choices [U]: the wear sign (SD42930) applies to the lengths and
// radius of W, E and S, not to [6]..[10]; other component letters (toolholder, orientation)
// are rejected as an invalid _COMP string (-3).
//
// Coordinate system after ':' — one of M, B, W, K, T; default MCS. No frames, mirroring or
// toolholder are modelled here, so all five give the same values (the suffix is validated).
//
// Transverse axis (MD20360 TOOL_PARAMETER_DEF_MASK): when a component is given as a diameter
// its value along the transverse axis (X by default) is halved. Choice [U]: bit 0 (value 1)
// = wear values (W, E, S) in diameter, bit 1 (value 2) = geometry and adapter (G, C) in
// diameter. The W1 manual example (N120..N150) halves both DP3 and DP12, i.e. mask 3.
#include <array>
#include <string_view>

#include "toolcomp/tools/sinumerik_edge.hpp"

namespace toolcomp::sinumerik {

// Status values. The order is the manual's; the numbers -1..-9 are assumed [U].
enum GettcorStatus : int {
    gettcor_ok = 0,
    gettcor_no_env_memory = -1,     // MD18116 = 0, no memory for tool environments
    gettcor_env_missing = -2,       // named tool environment (_STAT) does not exist
    gettcor_bad_comp = -3,          // invalid or duplicated character in _COMP
    gettcor_bad_t = -4,             // invalid T number
    gettcor_bad_d = -5,             // invalid D number
    gettcor_bad_dl = -6,            // invalid DL number
    gettcor_no_memory_module = -7,  // non-existent memory module (never returned here)
    gettcor_missing_option = -8,    // missing option (never returned here)
    gettcor_bad_coord = -9,         // ':' not followed by a valid coordinate-system letter
};

/// Tool environment for GETTCOR: plane, length settings, MD20360 diameter bits
struct GettcorSettings {
    /// 17, 18 or 19
    Plane plane = Plane::xy;            // active plane of the tool environment
    /// LengthSettings (a copy on read)
    SinumerikLengthSettings lengths;    // SD42940 / SD42950 / SD42930
    /// MD20360 bit 1
    bool geometry_diameter = false;
    /// MD20360 bit 0
    bool wear_diameter = false;
    /// 0 = X, 1 = Y, 2 = Z
    int transverse_axis = 0;            // geometry-axis index of the transverse axis (X)
    /// MD18116 MM_NUM_TOOL_ENV
    int tool_env_memory = 0;            // MD18116 MM_NUM_TOOL_ENV; no environments are stored

    /// MD20360 TOOL_PARAMETER_DEF_MASK: bit 0 wear, bit 1 geometry in diameter
    void set_parameter_def_mask(unsigned mask) {
        wear_diameter = (mask & 1u) != 0;
        geometry_diameter = (mask & 2u) != 0;
    }
};

// GETTCOR for one edge (the active T/D). `stat` names a tool environment: empty = current
// state; non-empty gives -1 (tool_env_memory == 0) or -2 (none stored). `dl`: -1 the active
// set, 0 no sum/setup offsets, else it must equal edge.dl (-6 otherwise). `len` is only
// written when the status is 0.
int gettcor(std::array<double, 11>& len, std::string_view comp, const SinumerikEdge& edge,
            const GettcorSettings& s = {}, std::string_view stat = {}, int dl = -1);

// GETTCOR with explicit _T and _D looked up in a parsed table: -4 when no edge of tool t
// exists, -5 when tool t exists but has no edge d.
int gettcor(std::array<double, 11>& len, std::string_view comp, const SinumerikEdgeMap& edges, int t,
            int d, const GettcorSettings& s = {}, std::string_view stat = {}, int dl = -1);

}  // namespace toolcomp::sinumerik
