"""Child process of the GL fallback: render one folder with this process's backend.

Reads ``{"out", "target", "options"}`` as JSON on stdin and prints one JSON line on stdout:
``{"ok": true, "summary": ...}``, or ``{"ok": false, "gl": true, "error": ...}`` when this
backend cannot render, or ``{"ok": false, "gl": false, "error": ..., "exit_code": ...}`` for any
other holomj error. The parent (:mod:`holomj.render.folder`) sets ``MUJOCO_GL``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from holomj.errors import HolomjError
from holomj.render.folder import RenderOptions, render_into
from holomj.render.gl import GLUnavailable


def main() -> int:
    """Run one render request from stdin; the reply goes to stdout."""
    request = json.loads(sys.stdin.read())
    options = RenderOptions(**{**request["options"], "views": tuple(request["options"]["views"])})
    try:
        summary = render_into(Path(request["out"]), Path(request["target"]), options)
    except GLUnavailable as err:
        reply = {"ok": False, "gl": True, "error": err.what}
    except HolomjError as err:
        reply = {"ok": False, "gl": False, "error": err.one_line(), "exit_code": err.exit_code}
    else:
        reply = {"ok": True, "summary": summary.to_dict()}
    sys.stdout.write(json.dumps(reply) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
