"""holomj: physically valid indoor scenes for MuJoCo.

The Python API (each name loads what it needs on first use, so ``import holomj`` stays light: no
MuJoCo, torch, OR-Tools or CoACD until a job runs)::

    import holomj
    res = holomj.generate("a small kitchen", "out/kitchen", seed=1)   # .folder .report .timings
    res = holomj.compile("house.json", "out/house")                   # any supported input
    rep = holomj.validate("out/house")                                # or a bare MJCF; repair=True
    holomj.render("out/house")                                        # renders/ and report.html
    holomj.export("out/house", "usd")                                 # or "glb", "urdf"
    ev = holomj.eval("out/house")                                     # .scores .details
    rf = holomj.refine("out/house", "add a plant in the corner")      # .ok .rounds .checks
    scene = holomj.Scene.load("out/house")                            # .objects .rooms .report
    lib = holomj.AssetLibrary.default()                               # built on first use

Errors are the :class:`holomj.HolomjError` types the command line prints.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from holomj.errors import HolomjError, InputError
from holomj.version import __version__

if TYPE_CHECKING:
    from holomj.api import (
        AssetLibrary,
        Scene,
        add_robot,
        compile,
        eval,
        export,
        generate,
        populate,
        refine,
        render,
        validate,
    )

__all__ = [
    "AssetLibrary",
    "HolomjError",
    "InputError",
    "Scene",
    "__version__",
    "add_robot",
    "compile",
    "eval",
    "export",
    "generate",
    "populate",
    "refine",
    "render",
    "validate",
]
_API = frozenset(__all__) - {"HolomjError", "InputError", "__version__"}


def __getattr__(name: str) -> Any:
    """Load an API name from :mod:`holomj.api` on first use."""
    if name in _API:
        from holomj import api

        value = getattr(api, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'holomj' has no attribute {name!r}")
