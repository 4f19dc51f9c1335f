"""Headless rendering of output folders: views, the annotated plan and the HTML report.

``render_folder(OUT)`` writes ``OUT/renders/``; ``write_report_html(OUT)`` writes
``OUT/report.html``. See :mod:`holomj.render.folder` and :mod:`holomj.render.report_html`.
"""

from holomj.render.folder import VIEW_NAMES, RenderSummary, render_folder
from holomj.render.report_html import write_report_html

__all__ = ["VIEW_NAMES", "RenderSummary", "render_folder", "write_report_html"]
