"""``python -m toolcomp``: see :mod:`toolcomp.cli`."""

import sys

from toolcomp.cli import main

if __name__ == "__main__":
    sys.exit(main())
