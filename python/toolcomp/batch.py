"""Running many programs at once.

:func:`run_many` runs programs on a thread pool. The engine releases the GIL while it reads
and runs a program, so the threads use every core. The same work maps onto a Dask bag when
one machine is not enough (see the README): each task runs :func:`toolcomp.run` on one
program and returns plain data.
"""
from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Iterable, List, Optional


def cores() -> int:
    """The cores this process may run on (its CPU affinity where the system tells it, else
    the machine's count)."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def run_many(programs: Iterable[Any], tools: Any = None, *, workers: Optional[int] = None,
             return_exceptions: bool = False, **kwargs: Any) -> List[Any]:
    """Run every program of ``programs`` (Program objects or paths) with ``tools`` (a
    ToolTable or a path, read once) on ``workers`` threads (default: the cores the process may use) and
    return their Results in the order given. ``kwargs`` are those of :func:`toolcomp.run`.
    When the workers alone keep every core busy (as many programs and workers as cores, or
    more), each run goes without threads of its own (``threads=False``: no hand-over between
    threads) unless ``threads`` is given.
    The first program that raises makes run_many raise that error, unless
    ``return_exceptions`` is true: then the error object takes that program's place."""
    from . import ToolTable, run  # the package's own run (paths, units, search path)

    if isinstance(programs, (str, bytes, os.PathLike)):
        raise TypeError("run_many takes a list of programs or paths; for one program use toolcomp.run")
    programs = list(programs)
    if isinstance(tools, (str, os.PathLike)):
        tools = ToolTable.read(os.fspath(tools), units=kwargs.pop("units", "mm"))
    if kwargs.get("machine") not in (None, "mill", "lathe"):  # a file or preset read once, not per program
        from .machine import resolve

        kwargs["machine"] = resolve(kwargs["machine"])
    if workers is None:
        workers = cores()
    if workers < 1:
        raise ValueError("workers must be at least 1")

    def one(program):
        try:
            return run(program, tools, **kwargs)
        except Exception as exc:  # noqa: BLE001 - handed back or re-raised in order
            if not return_exceptions:
                raise
            return exc

    if min(workers, len(programs)) >= cores():
        kwargs.setdefault("threads", False)
    if workers == 1 or len(programs) <= 1:
        return [one(p) for p in programs]
    with ThreadPoolExecutor(max_workers=min(workers, len(programs))) as pool:
        return list(pool.map(one, programs))
