"""Words: how annotation names and descriptions are normalised and looked up."""

from __future__ import annotations

import re
from typing import Any


def normalise(name: str) -> str:
    """Lower case, ``_``/``-`` as spaces, no articles, possessives or punctuation."""
    text = name.lower().replace("_", " ").replace("-", " ")
    text = re.sub(r"'s\b|’s\b", "", text)
    text = re.sub(r"[^a-z0-9 ]+", " ", text)
    words = [w for w in text.split() if w not in ("a", "an", "the")]
    return " ".join(words)


def singular_forms(name: str) -> list[str]:
    """Candidate singular forms of ``name`` (its last word made singular by English rules)."""
    words = name.split()
    if not words:
        return []
    last = words[-1]
    forms = []
    if last.endswith("ies") and len(last) > 4:
        forms.append(last[:-3] + "y")
    if last.endswith("ves") and len(last) > 4:
        forms += [last[:-3] + "f", last[:-3] + "fe"]
    if last.endswith("es") and len(last) > 3:
        forms.append(last[:-2])
    if last.endswith("s") and not last.endswith("ss") and len(last) > 2:
        forms.append(last[:-1])
    return [" ".join([*words[:-1], f]) for f in forms]


def slug(name: str) -> str:
    """``arcade cabinet`` -> ``arcade_cabinet`` (how an unknown name is looked for)."""
    return normalise(name).replace(" ", "_")


def id_noun(object_id: str) -> str:
    """The noun of a scene object's id: ``kitchen.arcade_cabinet_0`` -> ``arcade_cabinet``."""
    return re.sub(r"_?\d+$", "", str(object_id).split(".")[-1]).lower()


def find_words(text: str, table: dict[str, Any]) -> list[str]:
    """Entries of ``table`` found as whole words in ``text``, longest first, without overlaps."""
    words = normalise(text)
    found = []
    for entry in sorted(table, key=len, reverse=True):
        pattern = r"\b" + re.escape(entry) + r"\b"
        if re.search(pattern, words):
            found.append(entry)
            words = re.sub(pattern, " ", words)
    return found


def main_phrase(description: str) -> str:
    """The description up to its first "with"/"on"/"in"/"under"/"and"/comma clause."""
    text = " " + description.lower() + " "
    cut = len(text)
    for sep in (" with ", " on ", " in ", " under ", " and ", ","):
        pos = text.find(sep)
        if pos > 0:
            cut = min(cut, pos)
    return text[:cut].strip()
