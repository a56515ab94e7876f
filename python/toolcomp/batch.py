"""Running many programs at once.

:func:`run_many` runs programs on a thread pool. The engine releases the GIL while it reads
and runs a program, so the threads use every core. The same work maps onto a Dask bag when
one machine is not enough (see the README): each task runs :func:`toolcomp.run` on one
program and returns plain data.
"""
from __future__ import annotations

import inspect
import os
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Iterable, List, Optional, get_type_hints

from . import run as _run  # defined before the package imports this module

# run()'s keywords, their annotations evaluated (they are strings in __init__.py, names there)
_RUN_TYPES = get_type_hints(_run)
_RUN_KEYWORDS = {name: p.replace(annotation=_RUN_TYPES[name])
                 for name, p in inspect.signature(_run).parameters.items() if p.kind is p.KEYWORD_ONLY}


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
    return their Results in the order given. The other keywords are those of :func:`toolcomp.run`,
    passed on to it; a machine named by preset or file is read once too.
    When the workers alone keep every core busy (as many programs and workers as cores, or
    more), each run goes without threads of its own (``threads=False``: no hand-over between
    threads) unless ``threads`` is given (None, the default here: so decided).
    The first program that raises makes run_many raise that error, unless
    ``return_exceptions`` is true: then the error object takes that program's place."""
    import toolcomp

    if isinstance(programs, (str, bytes, os.PathLike)):
        raise TypeError("run_many takes a list of programs or paths; for one program use toolcomp.run")
    programs = list(programs)
    # What every run would read again, read once: run() takes them back as they are.
    if isinstance(tools, (str, os.PathLike)):
        tools = toolcomp._tools_input(tools, kwargs.pop("units", _RUN_KEYWORDS["units"].default))
    if "machine" in kwargs:
        kwargs["machine"] = toolcomp.machine.resolve(kwargs["machine"])
    if workers is None:
        workers = cores()
    if workers < 1:
        raise ValueError("workers must be at least 1")

    def one(program):
        try:
            return toolcomp.run(program, tools, **kwargs)  # looked up here: the package's run as it is now
        except Exception as exc:  # noqa: BLE001 - handed back or re-raised in order
            if not return_exceptions:
                raise
            return exc

    if kwargs.get("threads") is None:  # not given (or None): decided here
        kwargs.pop("threads", None)
        if min(workers, len(programs)) >= cores():
            kwargs["threads"] = False
    if workers == 1 or len(programs) <= 1:
        return [one(p) for p in programs]
    with ThreadPoolExecutor(max_workers=min(workers, len(programs))) as pool:
        return list(pool.map(one, programs))


def _signature() -> inspect.Signature:
    """run_many's signature as help() and the documentation show it: its own parameters,
    then the keywords of :func:`toolcomp.run` it passes on (taken from run, not written
    again)."""
    own = inspect.signature(run_many)
    types = get_type_hints(run_many)
    params = [p.replace(annotation=types[name]) for name, p in own.parameters.items() if p.kind is not p.VAR_KEYWORD]
    for name, p in _RUN_KEYWORDS.items():
        if name == "threads":  # chosen by run_many unless given
            p = p.replace(default=None, annotation=Optional[bool])
        params.append(p)
    return own.replace(parameters=params, return_annotation=types["return"])


run_many.__signature__ = _signature()  # type: ignore[attr-defined]
