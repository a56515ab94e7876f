"""The check the streaming tests share: chunks of a path (iter_run's, or a path read another
way) joined are the path, column for column and bit for bit (NaN equals NaN)."""
import numpy as np

COLUMNS = ("kind", "start", "end", "center", "abc", "line", "file", "tool", "feed", "side", "generated",
           "tool_offset", "plane", "turns", "normal", "tool_axis")


def joined(chunks):
    """The columns of `chunks` (Paths) joined end to end."""
    assert chunks, "no chunks"
    return {c: np.concatenate([np.asarray(getattr(x, c)) for x in chunks]) for c in COLUMNS}


def assert_same(path, chunks):
    """`chunks` joined are `path`: the same number of segments, every column equal."""
    cols = joined(chunks)
    assert len(cols["kind"]) == len(path)
    for c in COLUMNS:
        np.testing.assert_array_equal(cols[c], np.asarray(getattr(path, c)), err_msg=c)
