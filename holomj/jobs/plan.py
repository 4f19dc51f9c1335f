"""The plan job (``holomj plan``): a prompt in, a :class:`~holomj.spec.plan.ScenePlan` out,
nothing built; and the planner names every job that plans accepts."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from holomj.errors import InputError
from holomj.jobs.stage_log import Listener, StageLog

if TYPE_CHECKING:
    from holomj.spec.plan import ScenePlan

Planner = Literal["offline", "llm"]
PLANNERS: tuple[Planner, ...] = ("offline", "llm")


@dataclass(frozen=True)
class PlanOptions:
    """What the plan stage needs: the seed, which planner, the text model and the LLM server."""

    seed: int = 0
    planner: str = "offline"  # checked by check_planner
    text_model: Path | None = None
    llm_base_url: str | None = None
    llm_model: str | None = None
    llm_api_key: str | None = None
    llm_config: Path | None = None


def check_planner(planner: str) -> Planner:
    """``planner`` when it is a planner's name, else an InputError naming ``--planner``."""
    for name in PLANNERS:
        if planner == name:
            return name
    raise InputError(f"unknown planner {planner!r}", where="--planner", fix="use offline or llm")


def plan_scene(
    prompt: str,
    options: PlanOptions,
    *,
    library: Path | str | None = None,
    listener: Listener | None = None,
) -> ScenePlan:
    """The plan of ``prompt`` (offline, or from the LLM with the offline planner as fallback).

    The LLM planner is told the categories of ``library`` (default: the default library, built
    on first use); ``listener`` sees every log line of the plan stage as ``(stage, message)``.
    """
    from holomj.jobs.library import resolve_library
    from holomj.library.store import AssetLibrary

    check_planner(options.planner)
    categories: list[str] = []
    if options.planner == "llm":
        categories = AssetLibrary.open(resolve_library(library)).categories()
    return make_plan(prompt, options, categories, StageLog(listener))


def make_plan(prompt: str, options: PlanOptions, categories: list[str], log: StageLog) -> ScenePlan:
    """The plan of ``prompt``: offline, or from the LLM with the offline planner as fallback."""
    from holomj.plan.offline import plan_offline
    from holomj.retrieval.text import text_encoder

    def offline(text: str, seed: int) -> ScenePlan:
        # Without a chosen model the planner loads the default one itself, and only when a
        # scene type or object has to be matched by embedding.
        encoder = text_encoder(options.text_model) if options.text_model is not None else None
        return plan_offline(text, seed, encoder=encoder)

    if options.planner == "offline":
        return offline(prompt, options.seed)
    from holomj.plan.llm import plan_llm
    from holomj.plan.llm_config import load_llm_config

    config = load_llm_config(
        base_url=options.llm_base_url,
        model=options.llm_model,
        api_key=options.llm_api_key,
        config_file=options.llm_config,
    )
    return plan_llm(
        prompt,
        options.seed,
        config=config,
        fallback=offline,
        categories=categories,
        log=lambda line: log.info("plan", line),
    )
