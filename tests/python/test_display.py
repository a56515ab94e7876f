"""Jupyter's rich display: what a Result, Path, ToolTable and Diagnostic show (numbers worked
by hand from the program), text escaped, long tables cut with a count."""
import re

import toolcomp as tc

PROGRAM = "G0 X0 Y0\nG1 X10 F100\nG1 Y5\nG0 X0 Y0\nM30\n"  # feed 10 + 5, rapid sqrt(125)


def run(text=PROGRAM, **kw):
    return tc.run(tc.Program.parse(text, "fanuc"), **kw)


def test_a_result_shows_status_extent_lengths_and_a_picture():
    html = run()._repr_html_()
    assert "ran to the end" in html and "4 programmed and 4 compensated segments" in html
    assert "X 0.000 … 10.000, Y 0.000 … 5.000, Z 0.000 … 0.000" in html
    assert "15.000 mm at feed, 11.180 mm rapid" in html
    assert html.count("<polyline") == 2  # programmed and compensated
    # seen from above: the corner (10, 5) is the picture's top right, (10, 0) below it
    pts = [tuple(map(float, p.split(","))) for p in re.search(r'points="([^"]+)"', html).group(1).split()]
    assert pts[2][0] == pts[3][0] and pts[3][1] < pts[2][1]


def test_a_stopped_result_names_its_error_in_repr_and_display():
    res = run("G0 X0 Y0\nG1 X10 F0\nM30\n", strict=False)
    assert repr(res) == ("Result(ok=False, segments=1, diagnostics=1; zero_feed at line 2: "
                         "Cannot do g1 with zero feed rate)")
    html = res._repr_html_()
    assert "stopped" in html and "<code>zero_feed</code>" in html
    assert res.diagnostics[0]._repr_html_().count("<tr>") == 1


def test_a_path_and_a_lathe_path_drawn_from_the_front():
    html = run("G0 X0 Z0\nG1 X10 Z-20 F100\nM30\n").path._repr_html_()
    assert "toolcomp Path: 2 segments" in html and "<title>XZ</title>" in html


def test_a_tool_table_lists_its_tools_escaped_and_cut_after_fifty():
    t = tc.ToolTable()
    for n in range(1, 61):
        t.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=n / 10, length=[0.0, 0.0, 100.0 + n])], comment="<drill>"))
    html = t._repr_html_()
    assert "60 tools, units mm" in html and "… and 10 more" in html
    assert html.count("<tr>") == 51  # the header and fifty tools
    assert "<td>7</td><td>1</td><td>0.7</td><td>0, 0, 107</td>" in html
    assert "&lt;drill&gt;" in html and "<drill>" not in html
