"""Materials in a prompt, per surface: ``oak floor`` -> ``oak wood floor``.

A surface word (``floor``, ``walls``) takes the material and modifier words just before it,
named as the knowledge base writes that material for the surface; a material word with no
surface after it (``a carpeted bedroom``) goes to its usual surface when no object follows.
"""

from __future__ import annotations

from holomj.plan.prompt_reader import Reader
from holomj.plan.prompt_words import ADJECTIVE_RUN


def read_materials(reader: Reader) -> dict[str, str]:
    """``oak floor`` -> ``oak wood floor``; ``white walls`` -> ``white painted wall``."""
    out: dict[str, str] = {}
    words = reader.words
    for i, word in enumerate(words):
        surface = reader.index.surfaces.get(word)
        if surface is None or reader.used[i]:
            continue
        parts = _material_run(reader, i)
        if not parts:
            continue
        start = parts[0][0]
        description = _describe(reader, parts, surface)
        for k in range(start, i + 1):
            reader.used[k] = True
        if surface not in out:
            out[surface] = f"{description} {surface}"
    return out


def _material_run(reader: Reader, end: int) -> list[tuple[int, int, str | None]]:
    """(start, end, material key or None for a modifier) of the words before ``end``."""
    parts: list[tuple[int, int, str | None]] = []
    k = end
    while k > 0 and len(parts) < ADJECTIVE_RUN:
        hit: tuple[int, int, str | None] | None = None
        for size in range(min(3, k), 0, -1):
            words = tuple(reader.words[k - size : k])
            if words in reader.index.materials:
                hit = (k - size, k, reader.index.materials[words])
                break
        if hit is None and reader.words[k - 1] in reader.index.modifiers:
            hit = (k - 1, k, None)
        if hit is None or any(reader.used[hit[0] : hit[1]]):
            break
        parts.insert(0, hit)
        k = hit[0]
    return parts if any(p[2] is not None for p in parts) else []


def _describe(reader: Reader, parts: list[tuple[int, int, str | None]], surface: str) -> str:
    last = max(i for i, p in enumerate(parts) if p[2] is not None)
    words: list[str] = []
    for i, (start, end, key) in enumerate(parts):
        raw = " ".join(reader.words[start:end])
        if i == last and key is not None:
            words.append(reader.kb.materials[key].for_surface(surface) or raw)
        else:
            words.append(raw)
    return " ".join(words)


def lone_materials(reader: Reader, found: dict[str, str]) -> dict[str, str]:
    """Material words with no surface word after them (``a carpeted bedroom``)."""
    out: dict[str, str] = {}
    covered = {k for m in reader.mentions for k in range(m.start, m.end)}
    for i in range(len(reader.words)):
        if reader.used[i] or i in covered:
            continue
        for size in (3, 2, 1):
            words = tuple(reader.words[i : i + size])
            key = reader.index.materials.get(words)
            if key is None:
                continue
            term = reader.kb.materials[key]
            nxt = next((m for m in reader.mentions if m.start >= i + size), None)
            before_object = (
                nxt is not None
                and nxt.start <= i + size + 1
                and (nxt.meaning("object") or nxt.meaning("generic"))
            )
            if term.alone is not None and not before_object:
                surface = term.alone
                if surface not in found and surface not in out:
                    text = term.for_surface(surface) or " ".join(words)
                    out[surface] = f"{text} {surface}"
            break
    return out
