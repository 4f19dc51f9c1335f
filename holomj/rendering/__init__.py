"""Headless rendering in memory: views of a compiled scene, the annotated plan, the report page.

:func:`~holomj.rendering.pipeline.render_scene` renders a model and its scene into PNG images
(:class:`~holomj.rendering.pipeline.Rendering`); :func:`~holomj.rendering.report_html.render_page`
builds the HTML report from a scene, its reports and its images. Nothing here reads or writes an
output folder: the render job (:mod:`holomj.jobs.render`) does, with the OpenGL fallback to a
child process.
"""

from holomj.rendering.pipeline import (
    VIEW_NAMES,
    Rendering,
    RenderOptions,
    check_size,
    parse_views,
    render_scene,
)
from holomj.rendering.report_html import render_page

__all__ = [
    "VIEW_NAMES",
    "RenderOptions",
    "Rendering",
    "check_size",
    "parse_views",
    "render_page",
    "render_scene",
]
