"""The options and arguments more than one command takes, each declared once.

An option used by a single command is declared with that command. Values that need more than
a type or a range checked (a planner name, a render size, a profile) are mostly checked by the
jobs, so that the command line and the Python API reject them with the same one-line error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from holomj.seeds import MAX_SEED

# --- arguments ------------------------------------------------------------------------------

PromptArg = Annotated[str, typer.Argument(metavar="PROMPT", help="What to build, in words.")]
FolderArg = Annotated[
    Path,
    typer.Argument(
        metavar="OUT", help="A folder written by 'holomj compile' or 'holomj generate'."
    ),
]

# --- output ---------------------------------------------------------------------------------

OutFolderOption = Annotated[Path, typer.Option("--out", "-o", help="Output folder to create.")]
OutFileOption = Annotated[
    Path | None,
    typer.Option("--out", "-o", help="Write to this file instead of standard output."),
]
OverwriteOption = Annotated[bool, typer.Option("--overwrite", help="Replace OUT if it exists.")]
JsonOption = Annotated[bool, typer.Option("--json", help="Print the result as JSON.")]
QuietOption = Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing on success.")]
StrictOption = Annotated[
    bool,
    typer.Option(
        "--strict", help="Exit with 1 when the result is not ok (what counts: see above)."
    ),
]

# --- inputs ---------------------------------------------------------------------------------

SeedOption = Annotated[int, typer.Option("--seed", min=0, max=MAX_SEED, help="Random seed.")]
LibraryOption = Annotated[
    Path | None,
    typer.Option(
        "--library",
        help="Asset library folder (default: $HOLOMJ_HOME/library, built on first use).",
    ),
]
MaterialsOption = Annotated[
    Path | None,
    typer.Option(
        "--materials",
        help="User materials folder, filled by 'holomj materials import' (default: "
        "$HOLOMJ_HOME/materials).",
    ),
]

# --- scene building -------------------------------------------------------------------------

RobotOption = Annotated[
    str | None,
    typer.Option(
        "--robot",
        metavar="SPEC",
        help="Attach a robot on a free floor spot: an MJCF file, or panda (dm-robotics-panda, "
        "installed with --no-deps) or jaco (dm_control).",
    ),
]
ProfileOption = Annotated[
    str,
    typer.Option(
        "--profile",
        help="default, or mjx: primitive/low-vertex colliders and options MJX accepts.",
    ),
]
FurnitureOption = Annotated[
    str,
    typer.Option(
        "--furniture",
        help="How validation simulates furniture: free (all but the bolted-down fixtures: "
        "counters, base cabinets, cookers, sanitary ware; the report lists them), static "
        "(it keeps still), or, for validate only, as-is (the scene's own flags).",
    ),
]
RenderOption = Annotated[
    bool, typer.Option("--render/--no-render", help="Render views and report.html.")
]
RenderWidthOption = Annotated[
    int, typer.Option("--width", min=32, max=4096, help="Render width in pixels.")
]
RenderHeightOption = Annotated[
    int, typer.Option("--height", min=32, max=4096, help="Render height in pixels.")
]

# --- planning -------------------------------------------------------------------------------

PlannerOption = Annotated[
    str,
    typer.Option(
        "--planner",
        help="offline (knowledge base, no network) or llm (OpenAI-compatible endpoint from "
        "--llm-* options, HOLOMJ_LLM_* variables or $HOLOMJ_HOME/config.toml).",
    ),
]
TextModelOption = Annotated[
    Path | None,
    typer.Option(
        "--text-model",
        help="Local sentence-transformers model folder (default: the shipped all-MiniLM-L6-v2, "
        "or $HOLOMJ_TEXT_MODEL).",
    ),
]
LlmUrlOption = Annotated[
    str | None, typer.Option("--llm-base-url", help="e.g. http://localhost:11434/v1")
]
LlmModelOption = Annotated[str | None, typer.Option("--llm-model", help="Model name.")]
LlmKeyOption = Annotated[
    str | None, typer.Option("--llm-api-key", help="API key (or HOLOMJ_LLM_API_KEY).")
]
LlmConfigOption = Annotated[
    Path | None, typer.Option("--llm-config", help="TOML file with an [llm] table.")
]


def llm_settings(
    base_url: str | None, model: str | None, api_key: str | None, config_file: Path | None
) -> dict[str, Any]:
    """The ``--llm-*`` options as the jobs take them (None: from the environment and
    ``$HOLOMJ_HOME/config.toml``)."""
    return {"base_url": base_url, "model": model, "api_key": api_key, "config_file": config_file}
