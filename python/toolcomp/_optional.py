"""Optional dependencies, imported on use: a missing one names the extra that installs it."""
from __future__ import annotations

import importlib
from types import ModuleType


def require(module: str, extra: str, what: str) -> ModuleType:
    """Import ``module`` for ``what``; ImportError naming ``pip install 'toolcomp[extra]'``
    when it is not installed."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        package = module.split(".")[0]
        raise ImportError(f"{what} needs {package}, which is not installed: pip install 'toolcomp[{extra}]' "
                          f"(or pip install {package})") from e
