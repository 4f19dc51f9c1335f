"""The relation vocabulary, written once: every relation kind a prompt, a plan or an edit may
name, the words the prompt reader reads as it, the layout constraints it becomes, the edit
relation it is asked as and the annotation relation that judges it.

Everything else derives from :data:`RELATION_KINDS`: the plan's and the edit's relation
Literals (and so the JSON schemas), the prompt reader's table of words
(:mod:`holomj.plan.prompt_relations`), the offline planner's layout kinds
(:mod:`holomj.plan.relations`), the layout's expansion into constraints
(:mod:`holomj.layout.relation_constraints`), the edit's wishes (:mod:`holomj.edit.objects`),
the edit-instruction reader (:mod:`holomj.refinement.instruction`) and the scorer's reading of
a plan (:mod:`holomj.evaluation.plan_spec`).

- **A new word for a kind**: a phrase in :data:`PHRASE_FAMILIES` (``("abutting",): "by"``) or
  a place word in :data:`PLACE_WORDS`; a new family needs a ``read_from`` pair on the kind.
- **A new kind**: a row here (``constraints`` from the layout's constraint language,
  :mod:`holomj.layout.constraints`, and an ``expansion`` that exists); a new expansion is a
  builder in :mod:`holomj.layout.relation_constraints`, a new way of judging it a test in
  :mod:`holomj.evaluation.relations`.

Pure data: nothing here imports the rest of holomj.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

# How a kind's constraints are spread over the subject's instances (``k``) and the target's:
# ``each``: every subject instance gets them (to target instance ``k * targets // subjects``);
# ``mutual``: as ``each``, and the target's first instance gets them back to the subject's
# first; ``sides``: instance 2j is ``left of`` target j and 2j+1 ``right of`` it, each with the
# constraints; ``row``: instance k gets them to instance k-1; ``none``: no layout constraint
# (the plan's structure keeps it and the finished scene judges it).
Expansion = Literal["each", "mutual", "sides", "row", "none"]
Opening = Literal["window", "door"]


@dataclass(frozen=True)
class RelationFacts:
    """One relation kind.

    ``takes_target``: a relation to another object (else to a place of the room);
    ``constraints``: the layout constraint kinds each subject instance gets (see
    :data:`Expansion`); ``alone``: more of them when the subject has a single instance;
    ``planned``: a plan may carry it (the others only the prompt reader knows, and the planner
    turns into planned ones); ``edit_as``: the edit relation kind it is asked as (None: an edit
    cannot ask it); ``judged_as``: the annotation relation (:mod:`holomj.evaluation.relations`)
    and its target place ("" none, None the relation's own target) the scorer reads it as;
    ``opening``: the opening it is about; ``read_from``: the (phrase family, target) pairs the
    prompt reader reads as it (the target is a :data:`PLACE_WORDS` value, ``object`` or
    ``row``)."""

    kind: str
    takes_target: bool
    constraints: tuple[str, ...] = ()
    expansion: Expansion = "each"
    alone: tuple[str, ...] = ()
    planned: bool = True
    edit_as: str | None = None
    judged_as: tuple[str, str | None] | None = None
    opening: Opening | None = None
    read_from: tuple[tuple[str, str], ...] = ()


def _place(
    kind: str,
    constraint: str,
    judged: tuple[str, str],
    *read: tuple[str, str],
    opening: Opening | None = None,
    alone: tuple[str, ...] = (),
) -> RelationFacts:
    """A place of the room (no target) an edit may ask too."""
    return RelationFacts(
        kind,
        False,
        (constraint,),
        alone=alone,
        edit_as=kind,
        judged_as=judged,
        opening=opening,
        read_from=read,
    )


def _pair(
    kind: str,
    constraints: tuple[str, ...],
    judged: str,
    *read: tuple[str, str],
    expansion: Expansion = "each",
) -> RelationFacts:
    """A relation to another floor object an edit may ask too."""
    return RelationFacts(
        kind, True, constraints, expansion, edit_as=kind, judged_as=(judged, None), read_from=read
    )


# In the order of the schemas' enums (plan, then edit: places, then relations to an object).
RELATION_KINDS: tuple[RelationFacts, ...] = (
    _place("corner", "corner", ("in corner", ""), ("in", "corner")),
    _place("wall", "edge", ("against wall", "wall"),
           ("against", "wall"), ("on", "wall"), ("by", "wall"), ("near", "wall")),
    _place("middle", "middle", ("middle", ""), ("in", "middle"), ("at", "middle"),
           alone=("centre",)),  # one thing in the middle: at the room's centre
    _place("under_window", "under_window", ("under window", "window"), ("under", "window"),
           opening="window"),
    _place("by_window", "by_window", ("next to", "window"),
           ("front", "window"), ("by", "window"), ("near", "window"), ("at", "window"),
           opening="window"),
    _place("by_door", "by_door", ("near", "door"),
           ("front", "door"), ("by", "door"), ("near", "door"), ("at", "door"), ("in", "door"),
           opening="door"),
    _place("facing_window", "facing_window", ("facing", "window"), ("facing", "window"),
           opening="window"),
    _place("facing_door", "facing_door", ("facing", "door"),
           ("facing", "door"), ("across", "door"), opening="door"),
    _pair("adjacent_to", ("adjacent_to",), "next to", ("by", "object")),
    _pair("near", ("near",), "near", ("near", "object")),
    _pair("in_front_of", ("in_front_of",), "in front of", ("front", "object")),
    _pair("behind", ("behind",), "behind", ("behind", "object")),
    _pair("facing", ("face_to",), "facing", ("facing", "object")),
    _pair("across_from", ("face_to",), "across from", ("across", "object"), expansion="mutual"),
    _pair("around", ("adjacent_to", "face_to"), "around", ("around", "object"), ("at", "object")),
    RelationFacts("both_sides", True, ("adjacent_to", "face_same_as"), "sides",
                  edit_as="adjacent_to", judged_as=("next to", None),
                  read_from=(("sides", "object"),)),
    RelationFacts("in_row", False, ("adjacent_to", "face_same_as", "center_aligned"), "row",
                  read_from=(("row", "row"),)),
    RelationFacts("on", True, expansion="none", judged_as=("on", None),
                  read_from=(("on", "object"),)),
    RelationFacts("above", True, expansion="none", edit_as="above", judged_as=("above", None),
                  read_from=(("above", "object"),)),
    RelationFacts("ceiling", False, expansion="none",
                  read_from=(("from", "ceiling"), ("on", "ceiling"))),
    # Only the prompt reader's: an object under another (not planned), "X with Y" (the planner
    # decides: a small Y goes on X, a seat around it, anything else next to it).
    RelationFacts("under", True, expansion="none", planned=False,
                  read_from=(("under", "object"),)),
    RelationFacts("holds", True, expansion="none", planned=False,
                  read_from=(("with", "object"),)),
)  # fmt: skip
RELATIONS: dict[str, RelationFacts] = {facts.kind: facts for facts in RELATION_KINDS}

PLANNED_KINDS: tuple[str, ...] = tuple(f.kind for f in RELATION_KINDS if f.planned)
READ_KINDS: tuple[str, ...] = tuple(f.kind for f in RELATION_KINDS)
EDIT_KINDS: tuple[str, ...] = tuple(f.kind for f in RELATION_KINDS if f.edit_as == f.kind)
EDIT_PLACE_KINDS: tuple[str, ...] = tuple(k for k in EDIT_KINDS if not RELATIONS[k].takes_target)
EDIT_OBJECT_KINDS: tuple[str, ...] = tuple(k for k in EDIT_KINDS if RELATIONS[k].takes_target)
# Planned kinds the layout turns into constraints, and those the plan's structure keeps.
LAYOUT_KINDS = frozenset(f.kind for f in RELATION_KINDS if f.planned and f.constraints)
STRUCTURAL_KINDS = frozenset(f.kind for f in RELATION_KINDS if f.planned and not f.constraints)
# Edit relation kind of each kind an edit instruction may read (``both_sides``: next to).
EDIT_KIND_OF: dict[str, str] = {f.kind: f.edit_as for f in RELATION_KINDS if f.edit_as}
# The layout constraints each edit relation kind asks (``above`` is kept by the wall object).
EDIT_CONSTRAINTS: dict[str, tuple[str, ...]] = {
    k: RELATIONS[k].constraints for k in EDIT_KINDS if RELATIONS[k].constraints
}
# (phrase family, target) -> kind: how the prompt reader reads a relation phrase.
KIND_OF_WORDS: dict[tuple[str, str], str] = {
    pair: f.kind for f in RELATION_KINDS for pair in f.read_from
}


def kinds_about(opening: Opening) -> frozenset[str]:
    """The kinds that place an object by a window (``window``) or a door (``door``)."""
    return frozenset(f.kind for f in RELATION_KINDS if f.opening == opening)


# Literal types for pydantic (and so the JSON schemas), made from the table. A type checker
# sees plain strings; pydantic sees the Literal and checks every value against the table.
if TYPE_CHECKING:
    PlanRelationKind = str
    ReadRelationKind = str
    EditRelationKind = str
else:
    PlanRelationKind = Literal[PLANNED_KINDS]
    ReadRelationKind = Literal[READ_KINDS]
    EditRelationKind = Literal[EDIT_KINDS]


# --------------------------------------------------------------------------- words
# Phrases after an object (longest first when matched) and the family each stands for; a family
# reads as a kind by its target (:data:`KIND_OF_WORDS`).
PHRASE_FAMILIES: dict[tuple[str, ...], str] = {
    ("in",): "in",
    ("into",): "in",
    ("at",): "at",
    ("against",): "against",
    ("along",): "against",
    ("on",): "on",
    ("on", "top", "of"): "on",
    ("atop",): "on",
    ("under",): "under",
    ("below",): "under",
    ("beneath",): "under",
    ("underneath",): "under",
    ("by",): "by",
    ("next", "to"): "by",
    ("beside",): "by",
    ("besides",): "by",
    ("alongside",): "by",
    ("near",): "near",
    ("close", "to"): "near",
    ("nearby",): "near",
    ("in", "front", "of"): "front",
    ("behind",): "behind",
    ("facing",): "facing",
    ("face",): "facing",
    ("faces",): "facing",
    ("facing", "towards"): "facing",
    ("facing", "toward"): "facing",
    ("looking", "at"): "facing",
    ("pointed", "at"): "facing",
    ("turned", "towards"): "facing",
    ("across", "from"): "across",
    ("opposite",): "across",
    ("opposite", "to"): "across",
    ("opposite", "of"): "across",
    ("around",): "around",
    ("round",): "around",
    ("surrounding",): "around",
    ("on", "each", "side", "of"): "sides",
    ("on", "either", "side", "of"): "sides",
    ("on", "both", "sides", "of"): "sides",
    ("at", "each", "side", "of"): "sides",
    ("at", "either", "side", "of"): "sides",
    ("on", "each", "side"): "sides_of_previous",
    ("on", "either", "side"): "sides_of_previous",
    ("flanking",): "sides",
    ("above",): "above",
    ("over",): "above",
    ("from",): "from",
    ("with",): "with",
    ("side", "by", "side"): "row",
    ("in", "a", "row"): "row",
    ("in", "rows"): "row",
    ("in", "2", "rows"): "row",
    ("in", "a", "line"): "row",
    ("next", "to", "each", "other"): "row",
}
# Place words and the place each names.
PLACE_WORDS: dict[str, str] = {
    "wall": "wall", "walls": "wall", "corner": "corner", "corners": "corner",
    "middle": "middle", "center": "middle", "centre": "middle", "window": "window",
    "windows": "window", "door": "door", "doors": "door", "entrance": "door",
    "entry": "door", "doorway": "door", "ceiling": "ceiling",
}  # fmt: skip
