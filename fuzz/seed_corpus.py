"""Seed corpora for the fuzz targets: python3 fuzz/seed_corpus.py OUT_DIR

Writes OUT_DIR/<target>/<sha1 of the input> from the programs and tool tables the test
suites and examples use (tests/programs, examples) and the few inputs in fuzz/seeds/ for
what has no file there (Heidenhain and Sinumerik programs, Fanuc and 9/Series lathe
programs, Sinumerik tool data). Targets whose first byte selects a mode get that byte prepended (see
fuzz_iso_parse.cpp and fuzz_pipeline.cpp). Only the standard library: runs before any venv.
"""
import hashlib
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
SEEDS = ROOT / "fuzz" / "seeds"


def files(*patterns, where=("tests", "examples")):
    out = []
    for w in where:
        for p in patterns:
            out += sorted((ROOT / w).rglob(p))
    return [f for f in out if f.is_file() and "__pycache__" not in f.parts]


def main(out_dir):
    out = pathlib.Path(out_dir)
    ngc = files("*.ngc")
    fanuc = sorted((SEEDS / "fanuc").glob("*"))
    rockwell = sorted((SEEDS / "rockwell").glob("*"))
    heidenhain = sorted((SEEDS / "heidenhain").glob("*"))
    sinumerik = files("*.mpf", "*.spf") + sorted((SEEDS / "sinumerik").glob("*"))
    tc_dp = files("*.ini") + sorted((SEEDS / "tc_dp").glob("*"))
    corpora = {
        # first byte: 0 linuxcnc, 1 fanuc, 2 rockwell (strict); +3 lenient
        "fuzz_iso_parse": [(b"\x00", f) for f in ngc] + [(b"\x01", f) for f in fanuc]
        + [(b"\x02", f) for f in rockwell] + [(b"\x03", f) for f in ngc[:5]],
        "fuzz_heidenhain_parse": [(b"", f) for f in heidenhain],
        "fuzz_sinumerik_parse": [(b"", f) for f in sinumerik],
        # first byte: 0 linuxcnc, 1 fanuc, 2 fanuc lathe, 3 rockwell, 4 heidenhain,
        # 5 sinumerik profile, 6 fanuc profile, 7 sinumerik; +8 lenient
        "fuzz_pipeline": [(b"\x00", f) for f in ngc] + [(b"\x01", f) for f in fanuc]
        + [(b"\x02", f) for f in fanuc] + [(b"\x03", f) for f in rockwell]
        + [(b"\x04", f) for f in heidenhain] + [(b"\x05", f) for f in ngc if "comp" in f.parts]
        + [(b"\x06", f) for f in ngc if "comp" in f.parts] + [(b"\x07", f) for f in sinumerik]
        + [(b"\x08", f) for f in ngc if "errors" in f.parts],
        "fuzz_table_linuxcnc": [(b"", f) for f in files("*.tbl")],
        "fuzz_table_csv": [(b"", f) for f in files("*.csv")],
        "fuzz_table_json": [(b"", f) for f in files("*.json")],
        "fuzz_table_heidenhain": [(b"", f) for f in files("*.t", "*.T")],
        "fuzz_table_sinumerik": [(b"", f) for f in tc_dp],
        "fuzz_tc_dp": [(b"", f) for f in tc_dp],
    }
    for target, inputs in corpora.items():
        d = out / target
        d.mkdir(parents=True, exist_ok=True)
        for prefix, f in inputs:
            data = prefix + f.read_bytes()
            (d / hashlib.sha1(data).hexdigest()).write_bytes(data)
        print(f"{target}: {len(inputs)} seeds")


if __name__ == "__main__":
    main(sys.argv[1])
