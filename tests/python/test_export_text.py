"""The engine's text writers of a Path (cpp/src/path_gcode.cpp, path_csv.cpp) against plain
Python ones written from the same rules with Python's own float formatting
(reference_export.py; reference_csv below): byte for byte, on the example programs, on
random compensated contours and on values where fixed-point spelling is delicate (halves,
negative zeros, large and tiny numbers)."""
import csv
import io
import math
import pathlib
import random

import pytest

import toolcomp as tc
from toolcomp import _core, cli
from toolcomp.export import to_gcode

import reference_export

ROOT = pathlib.Path(__file__).resolve().parents[2]


def reference_csv(path, first_index=0):
    """The rows as the csv module writes them, numbers as f"{v:.6f}", NaN empty."""
    def num(v):
        return "" if v != v else f"{v:.6f}"

    names = {0: "rapid", 1: "line", 2: "arc_cw", 3: "arc_ccw"}
    out = io.StringIO(newline="")
    w = csv.writer(out)
    for i in range(len(path)):
        w.writerow([first_index + i, names[int(path.kind[i])], int(path.line[i]), int(path.tool[i]),
                    *(num(float(v[i, j])) for v in (path.start, path.end, path.center) for j in range(3)),
                    num(float(path.feed[i])), int(path.side[i]), int(path.generated[i]),
                    *(num(float(v[i, j])) for v in (path.tool_offset, path.abc) for j in range(3))])
    return out.getvalue()


def random_contour(seed):
    """A closed G41/G42 contour of lines and arcs with coordinates of up to 7 decimals (many
    at exact halves of the last printed digit), rotary words and feed changes."""
    rnd = random.Random(seed)
    lines = ["G21 G17 G90", "G0 X-40 Y-40 Z5", "G1 Z-1 F300", f"G4{rnd.choice('12')} D3 G1 X0 Y0 F500"]
    x = y = 0.0

    def w(v):  # G-code has no exponents
        return f"{v:.7f}".rstrip("0").rstrip(".")

    for _ in range(60):
        def coord(v):
            return round(v, rnd.choice((3, 6, 7)))
        nx, ny = coord(x + rnd.uniform(-30, 30)), coord(y + rnd.uniform(-30, 30))
        if rnd.random() < 0.1:
            nx = round(x + 0.0000005 * rnd.choice((1, -1, 3)), 7)  # sub-micron steps: words left out
        f = f" F{rnd.choice((500, 500.0000004, 800, 1234.5678905))}" if rnd.random() < 0.2 else ""
        a = f" A{w(round(rnd.uniform(-360, 360), rnd.choice((1, 7))))}" if rnd.random() < 0.1 else ""
        if rnd.random() < 0.3:
            g = rnd.choice(("G2", "G3"))
            lines.append(f"{g} X{w(nx)} Y{w(ny)} R{round(math.hypot(nx - x, ny - y) * rnd.uniform(0.51, 2), 4)}{f}")
        else:
            lines.append(f"G1 X{w(nx)} Y{w(ny)}{a}{f}")
        x, y = nx, ny
    lines += ["G1 X0 Y0", "G40 G0 X-40 Y-40", "M2"]
    return "\n".join(lines) + "\n"


def paths():
    tools = tc.ToolTable.read(ROOT / "examples/tools.tbl")
    yield tc.run(ROOT / "examples/pocket.ngc", tools=tools, start="machine_zero").path
    yield tc.run(tc.Program.parse("G21 G17 G0 X10 Y0\nG1 Z0 F300\nG3 X10 Y0 Z-6 I-10 J0 P3 F200\n"
                                  "G18 G2 X20 Z-6 I5 K0\nG19 G3 Y5 Z-1 J0 K5 P2\nG17 G2 X20 Y5 Z-3 I1 J-1 P4\nM2\n"), start="machine_zero").path
    table = tc.ToolTable.parse("T1 P1 D6.35 Z25.4\nT2 P2 D3\nT3 P3 D0.1\n", "linuxcnc")
    for seed in range(12):
        res = tc.run(tc.Program.parse(random_contour(seed)), tools=table, strict=False, start="machine_zero")
        yield res.path
        yield res.nominal


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "grbl"])
@pytest.mark.parametrize("kw", [{}, {"comments": False}, {"digits": 3}, {"digits": 0}, {"digits": 9},
                                {"digits": 12, "tool_length": False}])
def test_gcode_text_is_the_reference_writers(dialect, kw):
    count = 0
    for p in paths():
        try:
            expected = reference_export.to_gcode(p, dialect, **kw)
        except ValueError as exc:
            with pytest.raises(ValueError, match=str(exc)[:40]):
                to_gcode(p, dialect, **kw)
            continue
        assert to_gcode(p, dialect, **kw) == expected
        count += len(p)
    assert count > 1000


def test_csv_rows_are_the_reference_writers():
    for p in paths():
        assert _core._csv_header + _core._csv_rows(p, 0, len(p), 0) == \
            ",".join(cli.CSV_HEADER) + "\r\n" + reference_csv(p)
        # any stretch, numbered from anywhere
        a, b = len(p) // 3, 2 * len(p) // 3
        assert _core._csv_rows(p, a, b, 1000) == "".join(reference_csv(p, 1000 - a).splitlines(True)[a:b])
    assert _core._csv_rows(p, 5, 5, 0) == _core._csv_rows(p, len(p), len(p) + 9, 0) == ""


def test_spelling_by_hand():
    # In binary 0.0000005 and 12.3456785 lie just below a half of the last decimal written,
    # 0.0000015 just above; 2.5 with no decimals rounds to even; -0.0000004 is "-0.000000",
    # a zero once trimmed.
    res = tc.run(tc.Program.parse("G21 G0 X0.0000005 Y0.0000015 Z-0.0000004\nG1 X2.5 Y-0.4 F100.0000004\n"
                                  "G1 X12.3456785 Y1000 Z0\nM2\n"), start="machine_zero")
    p = res.path
    assert to_gcode(p, comments=False).splitlines() == [
        "G21 G90 G94 G40 G17 G91.1", "G0 X0 Y0.000002", "G1 X2.5 Y-0.4 F100", "G1 X12.345678 Y1000", "M2"]
    assert to_gcode(p, comments=False, digits=0).splitlines()[1:] == ["G0 X0", "G1 X2 F100", "G1 X12 Y1000", "M2"]
    rows = list(csv.reader(io.StringIO(_core._csv_rows(p, 0, len(p), 0))))
    assert rows[0][4:10] == ["0.000000"] * 4 + ["0.000002", "-0.000000"]
    assert rows[1][13] == "100.000000" and rows[2][7:9] == ["12.345678", "1000.000000"]
    assert rows[0][13] == "" and rows[0][10:13] == ["", "", ""]  # a rapid: no feed, no centre


def test_bad_arguments():
    p = tc.run(tc.Program.parse("G21 G1 X1 F100\nM2\n"), start="machine_zero").path
    with pytest.raises(ValueError, match="digits must be 0..30"):
        to_gcode(p, digits=31)
    with pytest.raises(ValueError, match="unknown export dialect"):
        to_gcode(p, "heidenhain")
