"""Importers: ProcTHOR/Holodeck houses and 3D-Generalist SceneDefs -> holomj SceneSpec."""

from holomj.importers.detect import detect_format, load_scene_input
from holomj.importers.procthor import import_procthor
from holomj.importers.result import ImportResult, Substitution
from holomj.importers.scenedef import import_scenedef

__all__ = [
    "ImportResult",
    "Substitution",
    "detect_format",
    "import_procthor",
    "import_scenedef",
    "load_scene_input",
]
