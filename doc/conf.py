"""Sphinx configuration of toolcomp's documentation: `make docs` builds it into build/docs/html.

The pages are the Markdown files of doc/ (MyST), the notebooks of notebooks/ (reached through
the link doc/notebooks, executed at every build) and the API reference, read by autodoc from
the installed module: build the module first (`make build`)."""
import os
import re
import subprocess
import sys

import toolcomp

HERE = os.path.dirname(os.path.abspath(__file__))

project = "toolcomp"
author = "toolcomp contributors"
copyright = "toolcomp contributors"
release = version = toolcomp.__version__

extensions = [
    "myst_nb",               # Markdown pages (MyST) and the notebooks
    "sphinx.ext.autodoc",    # the API reference, from the docstrings of the installed module
]

# gen_diagnostics.py writes diagnostics.md and is no page itself; _generated holds what this
# file writes at each build (the command line's help).
exclude_patterns = ["_build", "_generated", "**/.ipynb_checkpoints", "gen_diagnostics.py"]

html_theme = "furo"
html_title = f"toolcomp {release}"

# MyST: heading anchors, so that [Frames](#frames) and page.md#section links resolve.
myst_heading_anchors = 3
myst_enable_extensions = ["colon_fence"]

# Notebooks: run at every build (about 15 s for all nine), each in its own folder so that
# relative paths such as ../examples/tools.tbl hold; an error in a cell fails the build.
nb_execution_mode = "force"
nb_execution_timeout = 120
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True

# Docstrings: the compiled module's (pybind11) write `name` for code, the pure-Python modules
# ``name`` and :func: roles. Single backticks read as literal text.
default_role = "literal"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True}
autoclass_content = "class"
# The plugin's classes subclass pytest's; their inherited docstrings are pytest's, with
# references into pytest's own documentation.
autodoc_inherit_docstrings = False


def _clean_signature(app, what, name, obj, options, signature, return_annotation):
    """pybind11 signatures name the compiled module's classes toolcomp._core.X and start with
    `self: toolcomp._core.X`: show them as toolcomp.X and without self."""
    def clean(text):
        if text is None:
            return None
        text = re.sub(r"^\(self: [\w.]+(, )?", "(", text)
        return text.replace("toolcomp._core.", "toolcomp.")
    return clean(signature), clean(return_annotation)


_OVERLOAD = re.compile(r"^(\d+)\. (\w+\(.*)$")


def _overload_signatures(app, what, name, obj, options, lines):
    """pybind11 lists the signatures of an overloaded function as "1. name(..., *, x) -> y",
    which reStructuredText reads as text with an unclosed emphasis: show them as code."""
    for i, line in enumerate(lines):
        m = _OVERLOAD.match(line)
        if m:
            sig = re.sub(r"\(self: [\w.]+(, )?", "(", m.group(2)).replace("toolcomp._core.", "toolcomp.")
            lines[i] = f"{m.group(1)}. ``{sig}``"


_NOTEBOOK_LINK = re.compile(r"\]\((notebooks/[\w-]+)\.ipynb([)#])")


def _notebook_links(app, docname, source):
    """Pages link the notebooks as notebooks/x.ipynb (a working link on the repository's web
    view too). MyST resolves such a path through the link doc/notebooks to the real file,
    outside doc/, and finds no page: link the page by its name instead."""
    source[0] = _NOTEBOOK_LINK.sub(r"](\1\2", source[0])


def _write_cli_help():
    """The help of every command, as the installed version prints it (cli.md includes it)."""
    commands = [[], ["run"], ["check"], ["export"], ["tools"], ["tools", "show"], ["tools", "convert"],
                ["tools", "validate"]]
    env = dict(os.environ, COLUMNS="92")
    parts = []
    for c in commands:
        out = subprocess.run([sys.executable, "-m", "toolcomp", *c, "--help"], capture_output=True, text=True,
                             env=env, check=True).stdout
        parts.append(f"$ toolcomp {' '.join(c + ['--help'])}\n{out.rstrip()}\n")
    os.makedirs(os.path.join(HERE, "_generated"), exist_ok=True)
    path = os.path.join(HERE, "_generated", "cli-help.txt")
    text = "\n".join(parts)
    if not os.path.exists(path) or open(path).read() != text:  # unchanged: no rebuild of cli.md
        with open(path, "w") as f:
            f.write(text)


def _public_names_documented(app, env):
    """Every name of toolcomp.__all__ has its entry in the API reference (a warning, so an
    error under -W, when a new public name has none)."""
    from sphinx.util import logging

    objects = env.get_domain("py").objects
    for name in toolcomp.__all__:
        if not name.startswith("_") and f"toolcomp.{name}" not in objects:
            logging.getLogger(__name__).warning(
                f"toolcomp.{name} is public (toolcomp.__all__) but has no entry in doc/api/")


def setup(app):
    _write_cli_help()
    app.connect("source-read", _notebook_links)
    app.connect("autodoc-process-signature", _clean_signature)
    app.connect("autodoc-process-docstring", _overload_signatures)
    app.connect("env-check-consistency", _public_names_documented)
