"""``toolcomp tools``: show, convert and validate tool tables from the command line."""
from __future__ import annotations

import json
import os
import sys


def _read(path, units):
    from toolcomp.cli import _check_readable, _read_tools

    _check_readable(path, "tool table")
    return _read_tools(path, units)


def _table_error(path, exc) -> int:
    print(f"{path}:{exc.line}:{exc.column}: error {exc.code} {exc.message}", file=sys.stderr)
    return 1


def cmd_show(args) -> int:
    import toolcomp as tc
    try:
        table = _read(args.table, args.units)
    except tc.Error as exc:
        return _table_error(args.table, exc)
    rows = []
    for t in table:
        for e in t.edges:
            rows.append({"tool": t.number, "edge": e.number, "pocket": t.pocket, "name": t.name,
                         "length_z": float(e.effective_length[2]), "radius": e.effective_radius,
                         "orientation": e.orientation, "comment": t.comment})
    if args.format == "json":
        print(json.dumps(rows, indent=2))
        return 0
    print(f"{'tool':>5} {'D':>2} {'pocket':>6} {'length Z':>10} {'radius':>8} {'tip':>3}  name / comment")
    for r in rows:
        label = " / ".join(x for x in (r["name"], r["comment"]) if x)
        print(f"{r['tool']:>5} {r['edge']:>2} {r['pocket']:>6} {r['length_z']:>10.4f} {r['radius']:>8.4f} "
              f"{r['orientation']:>3}  {label}")
    print(f"{len(table)} tools, {table.units}")
    return 0


def cmd_convert(args) -> int:
    import toolcomp as tc
    try:
        table = _read(args.input, args.units)
    except tc.Error as exc:
        return _table_error(args.input, exc)
    if os.path.exists(args.output) and not args.force:
        print(f"toolcomp tools convert: {args.output} exists (use --force to replace it)", file=sys.stderr)
        return 2
    try:
        table.write(args.output)  # temporary file, fsync, rename: the old file is never half-written
    except (tc.Error, ValueError, OSError) as exc:  # a format that cannot hold it, an unknown suffix, no folder
        print(f"toolcomp tools convert: cannot write {args.output}: {exc}", file=sys.stderr)
        return 1
    return 0


def cmd_validate(args) -> int:
    import toolcomp as tc
    from toolcomp.tool_check import check_table
    failed = False
    for path in args.tables:
        try:
            table = _read(path, args.units)
        except tc.Error as exc:
            failed = True
            _table_error(path, exc)
            continue
        for d in check_table(table, lathe=args.lathe):
            print(f"{path}:{d.line}:{d.column}: {d.severity} {d.code} {d.message}")
            failed = failed or d.severity == "error" or (args.strict and d.severity == "warning")
    return 1 if failed else 0


def add_parser(sub) -> None:
    t = sub.add_parser("tools", help="show, convert and validate tool tables",
                       description="Tool tables: .tbl (LinuxCNC), .t (Heidenhain TOOL.T), .ini (Sinumerik $TC_DP), .csv, .json.")
    tsub = t.add_subparsers(dest="tools_command", metavar="ACTION")
    tsub.required = True

    def units(sp):
        sp.add_argument("--units", choices=("mm", "inch"), help="units of the table's lengths (default: mm)")

    s = tsub.add_parser("show", help="list the tools and their effective length and radius")
    s.add_argument("table", metavar="TABLE")
    s.add_argument("--format", choices=("text", "json"), default="text")
    units(s)
    s.set_defaults(func=cmd_show)

    c = tsub.add_parser("convert", help="write a table in another format (from the suffix)")
    c.add_argument("input", metavar="INPUT")
    c.add_argument("output", metavar="OUTPUT")
    c.add_argument("--force", action="store_true", help="replace OUTPUT if it exists")
    units(c)
    c.set_defaults(func=cmd_convert)

    v = tsub.add_parser("validate", help="check tables: pockets, radii, lathe tip orientations",
                        description="Print findings as file:line:column: severity code message; "
                                    "exit 1 if any is an error (or a warning with --strict).")
    v.add_argument("tables", metavar="TABLE", nargs="+")
    v.add_argument("--lathe", action="store_true", help="tools with a nose radius need a tip orientation")
    v.add_argument("--strict", action="store_true", help="warnings fail too")
    units(v)
    v.set_defaults(func=cmd_validate)
