"""Hand-written MJCF fragments shipped as package data (read them with :func:`template_path`)."""

from importlib import resources
from pathlib import Path


def template_path(name: str) -> Path:
    """Absolute path of a template file in this package, e.g. ``base_scene.xml``."""
    return Path(str(resources.files(__name__).joinpath(name)))
