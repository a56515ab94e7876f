"""Writing a text file users own: replaced atomically, its link and permissions kept."""
from __future__ import annotations

import os
import tempfile


def replace_text(path, text: str, suffix: str = "", errors: str = "strict") -> None:
    """Write `text` to `path` through a temporary file in the same folder, flushed to disk and
    renamed over it, so the file is never left half written. A link stays a link (its target
    is the file written) and an existing file keeps its permissions; the temporary file is
    removed when anything fails."""
    path = os.path.realpath(os.fspath(path))
    try:
        mode = os.stat(path).st_mode & 0o7777
    except FileNotFoundError:
        mode = None
    fd, tmp = tempfile.mkstemp(prefix=".toolcomp-", suffix=suffix, dir=os.path.dirname(path))
    try:
        with os.fdopen(fd, "w", encoding="utf-8", errors=errors, newline="") as f:
            f.write(text)
            f.flush()
            if mode is not None:
                os.fchmod(f.fileno(), mode)
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
