"""The floor-object constraint language: typed models, Holodeck's text format, warnings.

Five families, as in Holodeck (``ai2holodeck/generation/floor_objects.py``):

* global: ``edge`` (back against a wall), ``middle`` (not close to any wall);
* distance: ``near``, ``far`` (gap between the two footprints);
* position: ``in front of``, ``behind``, ``side of``, ``left of``, ``right of`` (in the target's
  own frame: its front, its left);
* alignment: ``center aligned`` (centres on one axis line);
* direction: ``face to`` (the object's front ray hits the target), ``face same as``,
  ``face opposite to``.

Beyond Holodeck, for what prompts say (:mod:`holomj.layout.place_relations`): the global
``corner`` (against both walls of a convex corner), ``centre`` (at the room's centre),
``under window`` (back to a window's wall,
under its span), ``by window`` (close to a window), ``by door`` (near a door), ``facing window``
and ``facing door`` (the front looks at one), and the distance
``adjacent to`` (footprints at most 45 cm apart: a prompt's "next to", "beside").

The text form is one line per object: ``coffee table-0 | middle | near, sofa-0 | face to,
sofa-0``. The parser is tolerant of layout (case, extra spaces, list numbering, ``*``, a final
full stop, ``_`` for a space in names) but never guesses a meaning: an unknown word, a missing or
unknown object name is dropped with a warning that says what was dropped and why. ``around`` is
Holodeck's documented shorthand for ``near`` + ``face to`` and is expanded (and says so in the
constraint's ``source``).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Annotated, Literal, get_args

from pydantic import Field, ValidationError, model_validator

from holomj.errors import SpecError, closest_names
from holomj.spec.base import FrozenModel

ConstraintKind = Literal[
    "edge",
    "middle",
    "corner",
    "centre",
    "under_window",
    "by_window",
    "by_door",
    "facing_window",
    "facing_door",
    "adjacent_to",
    "near",
    "far",
    "in_front_of",
    "behind",
    "side_of",
    "left_of",
    "right_of",
    "center_aligned",
    "face_to",
    "face_same_as",
    "face_opposite_to",
]
# Global kinds that place an object by the room's windows or doors, and by its corners too.
OPENING_KINDS = frozenset({"under_window", "by_window", "by_door", "facing_window", "facing_door"})
PLACE_KINDS = frozenset({"corner", "centre"}) | OPENING_KINDS
GLOBAL_KINDS = frozenset({"edge", "middle"}) | PLACE_KINDS
ALL_KINDS: tuple[str, ...] = get_args(ConstraintKind)

# The phrase that writes each kind in the text form.
KIND_PHRASE: dict[str, str] = {
    "edge": "edge",
    "middle": "middle",
    "corner": "corner",
    "centre": "center",  # phrases are read with "centre" spelled "center"
    "under_window": "under window",
    "by_window": "by window",
    "by_door": "by door",
    "facing_window": "facing window",
    "facing_door": "facing door",
    "adjacent_to": "adjacent to",
    "near": "near",
    "far": "far",
    "in_front_of": "in front of",
    "behind": "behind",
    "side_of": "side of",
    "left_of": "left of",
    "right_of": "right of",
    "center_aligned": "center aligned",
    "face_to": "face to",
    "face_same_as": "face same as",
    "face_opposite_to": "face opposite to",
}
# Every phrase the parser accepts (after normalisation) and the kinds it stands for. Synonyms are
# listed here on purpose: anything else is an unknown word and gets a warning.
PHRASES: dict[str, tuple[str, ...]] = {
    **{phrase: (kind,) for kind, phrase in KIND_PHRASE.items()},
    "around": ("near", "face_to"),
    "aligned": ("center_aligned",),
    "center alignment": ("center_aligned",),
    "aligned center": ("center_aligned",),
    "center align": ("center_aligned",),
    "centered": ("center_aligned",),
    "face towards": ("face_to",),
    "facing": ("face_to",),
    "next to": ("side_of",),
    "beside": ("side_of",),
    "in corner": ("corner",),
    "in the corner": ("corner",),
    "near window": ("by_window",),
    "near door": ("by_door",),
}
_IGNORED = frozenset({"", "n/a", "na", "none", "-"})

# Object names in layout problems: Holodeck's (``coffee table-0``) or identifiers. No ``|`` or
# ``,``: they separate fields in the text form.
ObjectName = Annotated[
    str, Field(min_length=1, max_length=128, pattern=r"^[A-Za-z0-9_][A-Za-z0-9_ .:+\-]*$")
]


RELATION_WEIGHT = 10.0  # a constraint the prompt asked for (the templates' defaults weigh 1)


class Constraint(FrozenModel):
    """One soft constraint on ``object``: a global one, or a relation to ``target``."""

    object: ObjectName
    kind: ConstraintKind
    target: ObjectName | None = None
    weight: Annotated[float, Field(gt=0.0, le=100.0)] = 1.0
    source: str | None = Field(
        default=None, max_length=1000, description="The text line it was parsed from, if any."
    )

    @model_validator(mode="after")
    def _target_matches_kind(self) -> Constraint:
        # ValueError (not SpecError) so that pydantic reports the list index of the constraint.
        if self.kind in GLOBAL_KINDS and self.target is not None:
            raise ValueError(f"'{self.kind}' takes no target")
        if self.kind not in GLOBAL_KINDS and self.target is None:
            raise ValueError(f"'{self.kind}' needs a target object")
        if self.target is not None and normalize_name(self.target) == normalize_name(self.object):
            raise ValueError("an object cannot be constrained relative to itself")
        return self

    @property
    def text(self) -> str:
        """The constraint in Holodeck's text form, e.g. ``coffee table-0 | near, sofa-0``."""
        phrase = KIND_PHRASE[self.kind]
        body = phrase if self.target is None else f"{phrase}, {self.target}"
        return f"{self.object} | {body}"

    @property
    def key(self) -> tuple[str, str, str | None]:
        """Identity for de-duplication."""
        return (self.object, self.kind, self.target)


@dataclass
class ParsedConstraints:
    """What the text parser found, plus one warning per thing it had to drop."""

    constraints: list[Constraint] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def normalize_name(name: str) -> str:
    """Lower case, ``_`` as a space, ``*`` and backticks removed, whitespace collapsed."""
    cleaned = name.replace("*", "").replace("`", "").replace("_", " ").lower()
    return " ".join(cleaned.split())


def normalize_phrase(phrase: str) -> str:
    """Lower case, collapsed whitespace, British ``centre`` spelled ``center``."""
    cleaned = " ".join(phrase.replace("*", "").replace("_", " ").lower().split())
    return cleaned.replace("centre", "center")


_NUMBERING = re.compile(r"^\s*(?:\d+\s*[.):]\s*|[-•]\s+)")


def parse_constraint_text(text: str, object_ids: Sequence[str] | None = None) -> ParsedConstraints:
    """Parse Holodeck's constraint lines; names resolve to ``object_ids`` when given.

    Lines without ``|`` (an LLM's prose around the plan) are skipped and counted in one warning.
    """
    result = ParsedConstraints()
    lookup = _name_lookup(object_ids) if object_ids is not None else None
    skipped_prose = 0
    seen: set[tuple[str, str, str | None]] = set()
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line:
            continue
        if "|" not in line:
            if line.strip("`").strip():
                skipped_prose += 1
            continue
        line = _NUMBERING.sub("", line).strip().rstrip(".").strip()
        fields = line.split("|")
        where = f"line {number}"
        name = _resolve(fields[0], lookup, result.warnings, f"{where}: object", raw)
        if name is None:
            continue
        for segment in fields[1:]:
            for constraint in _parse_segment(segment, name, lookup, result.warnings, where, raw):
                if constraint.key in seen:
                    result.warnings.append(
                        f"{where}: duplicate constraint {constraint.text!r} ignored"
                    )
                    continue
                seen.add(constraint.key)
                result.constraints.append(constraint)
    if skipped_prose:
        result.warnings.append(
            f"{skipped_prose} line{'s' if skipped_prose > 1 else ''} without '|' skipped "
            "(not constraint lines)"
        )
    return result


def _parse_segment(
    segment: str,
    name: str,
    lookup: dict[str, str] | None,
    warnings: list[str],
    where: str,
    raw: str,
) -> list[Constraint]:
    parts = [p.strip() for p in segment.split(",")]
    phrase = normalize_phrase(parts[0])
    if phrase in _IGNORED and len(parts) == 1:
        return []
    kinds = PHRASES.get(phrase)
    if kinds is None:
        close = closest_names(phrase, PHRASES)
        hint = f"; did you mean: {close}" if close else ""
        warnings.append(
            f"{where}: unknown constraint {parts[0].strip()!r} for {name!r} ignored "
            f"(known: {', '.join(KIND_PHRASE.values())}, around{hint})"
        )
        return []
    target_text = ",".join(parts[1:]).strip()
    if len(parts) > 2:
        warnings.append(
            f"{where}: {segment.strip()!r} has more than one target; used {target_text!r}"
        )
    if kinds[0] in GLOBAL_KINDS:
        if target_text:
            warnings.append(
                f"{where}: {phrase!r} takes no target; {target_text!r} ignored for {name!r}"
            )
        return _build(warnings, where, [{"object": name, "kind": kinds[0]}], raw)
    if not target_text:
        warnings.append(f"{where}: {phrase!r} for {name!r} has no target object; ignored")
        return []
    target = _resolve(target_text, lookup, warnings, f"{where}: target of {phrase!r}", raw)
    if target is None:
        return []
    if normalize_name(target) == normalize_name(name):
        warnings.append(f"{where}: {name!r} cannot be {phrase!r} itself; ignored")
        return []
    return _build(
        warnings, where, [{"object": name, "kind": k, "target": target} for k in kinds], raw
    )


def _build(
    warnings: list[str], where: str, items: list[dict[str, str]], raw: str
) -> list[Constraint]:
    try:
        return [Constraint.model_validate({**item, "source": raw.strip()[:1000]}) for item in items]
    except ValidationError as err:
        problem = err.errors(include_url=False)[0].get("msg", "invalid")
        warnings.append(f"{where}: {raw.strip()!r} ignored ({problem})")
        return []


def _name_lookup(object_ids: Iterable[str]) -> dict[str, str]:
    lookup: dict[str, str] = {}
    for object_id in object_ids:
        key = normalize_name(object_id)
        if key in lookup and lookup[key] != object_id:
            raise SpecError(
                f"object ids {lookup[key]!r} and {object_id!r} are the same name in the text "
                "form (case, '_' and spaces are ignored there)",
                where="objects",
                fix="rename one of them",
            )
        lookup[key] = object_id
    return lookup


def _resolve(
    text: str, lookup: dict[str, str] | None, warnings: list[str], what: str, raw: str
) -> str | None:
    key = normalize_name(text)
    if not key:
        warnings.append(f"{what}: missing object name in {raw.strip()!r}; ignored")
        return None
    if lookup is None:
        return key
    if key in lookup:
        return lookup[key]
    close = closest_names(key, lookup)
    hint = f" (did you mean: {close})" if close else ""
    warnings.append(f"{what}: unknown object {text.strip()!r}{hint}; ignored")
    return None


def constraints_to_text(constraints: Iterable[Constraint]) -> str:
    """Render constraints in Holodeck's text form, one line per object, globals first."""
    by_object: dict[str, list[Constraint]] = {}
    for constraint in constraints:
        by_object.setdefault(constraint.object, []).append(constraint)
    lines = []
    for name, items in by_object.items():
        items = sorted(items, key=lambda c: c.kind not in GLOBAL_KINDS)
        parts = [
            KIND_PHRASE[c.kind] if c.target is None else f"{KIND_PHRASE[c.kind]}, {c.target}"
            for c in items
        ]
        lines.append(" | ".join([name, *parts]))
    return "\n".join(lines) + ("\n" if lines else "")
