"""Segment-by-segment comparison of toolcomp's nominal path with rs274's moves (tests/oracle/lcnc.py).

Rules (documented here because they are the oracle's definition of "equal"):

* Both sides are in millimetres. The tolerance is rs274's print precision: 6e-5 program units
  (x25.4 for moves made while the program was in inches), per coordinate.
* Lines and rapids: same kind, same end, same ABC, same tool_offset, same feed (NaN for rapids).
  ``start`` is compared with 3x the tolerance (rs274's start is derived from rounded printed values).
* Arcs: rs274 emits ONE ARC_FEED per programmed arc, with ``turn = +-n`` for P=n (n-1 extra full
  revolutions; a full circle is start == end with turn +-1). toolcomp may report the same arc as one
  segment or split it (e.g. per revolution). A run of consecutive toolcomp arc segments with the same
  direction and the same in-plane centre is matched to one rs274 arc when the sum of their swept
  angles equals rs274's swept angle (|turn|-1 full turns + the start->end angle, 2*pi when start == end);
  the last segment's end must equal rs274's end. Only the two in-plane centre components are compared
  (rs274 has no centre coordinate along the plane normal).
"""
from __future__ import annotations

import math

import numpy as np

import lcnc


class Mismatch(AssertionError):
    pass


def _get(path, name):
    return np.asarray(getattr(path, name))


def toolcomp_columns(path) -> dict:
    cols = {}
    for name in ("kind", "start", "end", "center", "abc", "tool_offset", "feed"):
        cols[name] = _get(path, name)
    cols["kind"] = cols["kind"].astype(np.int64)
    cols["turns"] = _get(path, "turns").astype(np.int64)  # extra full turns of each arc
    return cols


def _close(a, b, tol):
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    nan_a, nan_b = np.isnan(a), np.isnan(b)
    if np.any(nan_a != nan_b):
        return False
    ok = nan_a | (np.abs(np.where(nan_a, 0, a) - np.where(nan_b, 0, b)) <= tol)
    return bool(np.all(ok))


def _fmt(cols, j):
    return ("kind=%d start=%s end=%s center=%s abc=%s tlo=%s feed=%s"
            % (cols["kind"][j], cols["start"][j], cols["end"][j], cols["center"][j],
               cols["abc"][j], cols["tool_offset"][j], cols["feed"][j]))


def compare(rs: dict, tc, label: str = "") -> None:
    """Raise Mismatch with a readable message at the first difference."""
    t = tc if isinstance(tc, dict) else toolcomp_columns(tc)
    n_rs, n_tc = len(rs["kind"]), len(t["kind"])
    j = 0
    for i in range(n_rs):
        tol = lcnc.PRINT_TOL * rs["units"][i]
        kind = int(rs["kind"][i])

        def fail(msg):
            raise Mismatch("%s: rs274 move #%d (kind %d, end %s, centre %s, turns %d) vs toolcomp "
                           "segment #%d: %s\n  toolcomp: %s"
                           % (label, i, kind, rs["end"][i], rs["center"][i], rs["turns"][i], j, msg,
                              _fmt(t, j) if j < n_tc else "<no more segments>"))

        if j >= n_tc:
            fail("toolcomp has only %d segments, rs274 has %d moves" % (n_tc, n_rs))
        if int(t["kind"][j]) != kind:
            fail("kind differs")
        first = j
        if kind in (lcnc.RAPID, lcnc.LINE):
            last = j
            j += 1
        else:
            plane = int(rs["plane"][i])
            a, b, _ = lcnc.plane_axes(plane)
            cw = kind == lcnc.ARC_CW
            r = math.hypot(rs["start"][i][a] - rs["center"][i][a], rs["start"][i][b] - rs["center"][i][b])
            want = lcnc.sweep(rs["start"][i], rs["end"][i], rs["center"][i], cw, plane,
                              rs["turns"][i], tol=10 * tol)
            ang_tol = 20 * tol / max(r, 1e-9)
            got = 0.0
            last = j
            while True:
                if j >= n_tc or int(t["kind"][j]) != kind:
                    fail("arc sweep %.9f rad not reached: toolcomp segments sum to %.9f" % (want, got))
                c = t["center"][j]
                if not (_close(c[a], rs["center"][i][a], tol) and _close(c[b], rs["center"][i][b], tol)):
                    fail("arc centre differs (in-plane components)")
                extra = int(t["turns"][j]) if "turns" in t else 0
                got += lcnc.sweep(t["start"][j], t["end"][j], c, cw, plane, 1 + extra,
                                  tol=10 * tol)
                last = j
                j += 1
                if got >= want - ang_tol:
                    break
            if abs(got - want) > ang_tol:
                fail("arc sweep differs: rs274 %.9f rad, toolcomp %.9f rad" % (want, got))
        if not _close(t["end"][last], rs["end"][i], tol):
            fail("end differs (toolcomp segment #%d)" % last)
        # rs274 prints no start points; the harness takes the previous end. Where toolcomp's
        # path itself jumps (G88: the operator retracts by hand), there is nothing to compare.
        jump = first > 0 and not _close(t["start"][first], t["end"][first - 1], tol)
        if not jump and not _close(t["start"][first], rs["start"][i], 3 * tol):
            fail("start differs (toolcomp segment #%d)" % first)
        if not _close(t["abc"][last], rs["abc"][i], lcnc.PRINT_TOL):
            fail("abc differs")
        if not _close(t["tool_offset"][last], rs["tool_offset"][i], tol):
            fail("tool_offset differs: rs274 %s" % rs["tool_offset"][i])
        css = np.isnan(rs["feed"][i]) and rs["kind"][i] != lcnc.RAPID  # G96 per revolution: not known
        # A synchronised move's lead is printed with 6 decimals: its feed is known to that.
        feed_tol = rs["feed_tol"][i] if "feed_tol" in rs else 0.0
        if not css and not _close(t["feed"][last], rs["feed"][i],
                                  max(tol, feed_tol, 1e-9 * abs(np.nan_to_num(rs["feed"][i])))):
            fail("feed differs: rs274 %s" % rs["feed"][i])
    if j != n_tc:
        raise Mismatch("%s: toolcomp has %d extra segments after rs274's %d moves; next: %s"
                       % (label, n_tc - j, n_rs, _fmt(t, j)))
