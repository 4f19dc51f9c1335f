"""SceneSpec -> MjSpec -> compiled MuJoCo model. The only place that builds MJCF."""

from holomj.mjcf.compiler import CompiledScene, compile_scene

__all__ = ["CompiledScene", "compile_scene"]
