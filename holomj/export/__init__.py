"""The single writer of output folders."""

from holomj.export.writer import export_scene, prepare_output

__all__ = ["export_scene", "prepare_output"]
