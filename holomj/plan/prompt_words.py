"""The words of a prompt: tokens, number words, markers and the word lists parsing reads by.

:func:`tokenize` splits a prompt into lower-case words, digits and punctuation (accents and
``'s`` dropped, ``m²`` and ``sq ft`` as ``sqm`` and ``sqft``); :func:`normalise_words` turns
number words into digits (``twenty five`` -> 25, ``a dozen`` -> 12) and quantity and negation
phrases into the markers :data:`MANY` and :data:`NEG`. The word sets (head ends, list starts and
ends, separators, determiners, stopwords, people) are shared by the parsing modules.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Sequence

MANY = "MANY"  # marker token for "lots of", "many", "loves", ...
NEG = "NEG"  # marker token for "without", "no"
MAX_PHRASE_WORDS = 5
ADJECTIVE_RUN = 4  # words looked back from a match for its quantity and adjectives

_NUMBERS = {
    "zero": 0, "none": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6,
    "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13,
    "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
    "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60,
    "seventy": 70, "eighty": 80, "ninety": 90, "dozen": 12, "couple": 2, "pair": 2,
    "few": 3, "several": 3, "handful": 3,
}  # fmt: skip
_TENS = {"twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"}
_SCALES = {"hundred": 100, "thousand": 1000}
# Multi-word quantity phrases, replaced before numbers are read (longest first).
_PHRASES: list[tuple[tuple[str, ...], tuple[str, ...]]] = [
    (("a", "lot", "of"), (MANY,)),
    (("lots", "of"), (MANY,)),
    (("lot", "of"), (MANY,)),
    (("plenty", "of"), (MANY,)),
    (("loads", "of"), (MANY,)),
    (("tons", "of"), (MANY,)),
    (("a", "bunch", "of"), (MANY,)),
    (("bunch", "of"), (MANY,)),
    (("dozens", "of"), (MANY,)),
    (("hundreds", "of"), (MANY,)),
    (("full", "of"), ("with", MANY)),
    (("filled", "with"), ("with", MANY)),
    (("packed", "with"), ("with", MANY)),
    (("obsessed", "with"), (MANY,)),
    (("a", "couple", "of"), ("2",)),
    (("couple", "of"), ("2",)),
    (("a", "pair", "of"), ("2",)),
    (("pair", "of"), ("2",)),
    (("a", "few"), ("3",)),
    (("a", "handful", "of"), ("3",)),
    (("handful", "of"), ("3",)),
    (("a", "dozen"), ("12",)),
    (("a", "hundred"), ("100",)),
    (("a", "thousand"), ("1000",)),
    (("as", "well", "as"), ("and",)),
    (("along", "with"), ("with",)),
    (("do", "not", "want"), (NEG,)),
    (("dont", "want"), (NEG,)),
    (("no", "need", "for"), (NEG,)),
    (("free", "of"), (NEG,)),
]
_MANY_WORDS = {"many", "numerous", "loves", "love", "loving", "adores", "adore", "countless"}
_NEG_WORDS = {"without", "no", "not", "never", "except"}
# Words that end the head of a prompt (what comes before them names the scene).
HEAD_END = {
    "with", "for", "who", "that", "which", "where", "featuring", "including", "containing",
    "has", "having", "plus", "and", ",", ".", ";", ":", "!", "?", "(", ")", "in", "but",
    "whose", "near", "next", "like", "to", "on", NEG,
}  # fmt: skip
# Words that open a list of things wanted in the room.
WITH_START = {"with", "featuring", "including", "containing", "has", "having", "plus", "add"}
# Words that close such a list (a new clause starts).
WITH_END = {"for", "who", "that", "which", "where", "whose", ".", ";", "!", "?", "but", "so"}
SEPARATORS = {",", "and", "or", "&", "plus", "with", "also", "then", "(", ")", ":"}
DETERMINERS = {"a", "an", "the", "some", "one", "any", "each", "every", "another", "extra"}
STOPWORDS = {
    "a", "an", "the", "some", "of", "to", "in", "on", "at", "by", "from", "into", "onto", "its",
    "it", "their", "my", "our", "your", "his", "her", "this", "these", "those", "very", "really",
    "quite", "nice", "beautiful", "lovely", "pretty", "great", "good", "new", "old", "also", "too",
    "please", "i", "we", "want", "need", "like", "would", "be", "is", "are", "there", "have",
    "room", "rooms", "space", "area", "place", "corner", "side", "each", "every", "one", "ones",
    "other", "another", "more", "extra", "enough", "lot", "lots", "all", "any", "both", "own", "s",
    "just", "only", "even", "well", "as", "so", "much", "little", "bit", "set", "sets", "kind",
    "kinds", "type", "types", "style", "styled", "themed", "looking", "plenty", "tons", "loads",
    "bunch", "couple", "pair", "number", "few", "several", "against", "along", "around", "under",
    "over", "above", "below", "between", "behind", "front", "middle", "center", "centre", "near",
    "next", "beside", "up", "down", "out", "off", "for", "who", "that", "which", "where", "whose",
    "but", "or", "and", "with", "without", "featuring", "including", "containing", "has", "having",
    "plus", "add", "put", "placed", "filled", "full", "big", "large", "small", "huge", "tiny",
    "medium", "here", "them", "they", "he", "she", "you", "me", "us", "can", "could", "should",
    "will", "make", "made", "give", "get", "include", "includes", "included", "decorated",
    "furnished",
}  # fmt: skip
ROOM_WORDS = {"room", "rooms", "space", "area", "place", "scene", "interior"}
PEOPLE = {
    "people", "persons", "person", "guests", "guest", "students", "student", "kids", "children",
    "pupils", "diners", "employees", "workers", "seats", "users", "players", "musicians",
    "patients", "visitors", "colleagues", "staff", "learners", "toddlers", "adults", "friends",
    "participants", "attendees", "customers", "family", "members",
}  # fmt: skip


def tokenize(text: str) -> list[str]:
    """Lower-case words, digits (``2.5``) and punctuation of ``text``; ``'s`` dropped."""
    text = unicodedata.normalize("NFKD", text)
    text = "".join(c for c in text if not unicodedata.combining(c)).lower()
    text = re.sub(r"[\u2018\u2019`\u00b4]", "'", text).replace("\u00d7", " x ")
    text = re.sub(r"'s\b", "", text).replace("'", "")
    text = re.sub(
        r"(\d)\s*(?:m\^?2|sq\.?\s*m|sqm|square\s+met(?:er|re)s?|square\s+m)\b", r"\1 sqm ", text
    )
    text = re.sub(r"(\d)\s*(?:ft\^?2|sq\.?\s*ft|sqft|square\s+f(?:ee|oo)t)\b", r"\1 sqft ", text)
    return re.findall(r"\d+(?:\.\d+)?|[a-z]+|[,.;:!?()&*]", text)


def normalise_words(tokens: Sequence[str]) -> list[str]:
    """Number words to digits and quantity phrases to markers (:data:`MANY`, :data:`NEG`)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        for phrase, replacement in _PHRASES:
            if tuple(tokens[i : i + len(phrase)]) == phrase:
                out.extend(replacement)
                i += len(phrase)
                break
        else:
            word = tokens[i]
            if word in _MANY_WORDS:
                out.append(MANY)
            elif word in _NEG_WORDS:
                out.append(NEG)
            elif word in _NUMBERS or word in _SCALES:
                value, i = _read_number(tokens, i)
                out.append(str(value))
                continue
            else:
                out.append(word)
            i += 1
    return out


def _read_number(tokens: Sequence[str], i: int) -> tuple[int, int]:
    """Read ``twenty five``, ``two hundred``, ``two dozen`` from ``tokens[i]``."""
    word = tokens[i]
    value = _SCALES.get(word, _NUMBERS.get(word, 0))
    i += 1
    if word in _TENS and i < len(tokens) and tokens[i] in _NUMBERS and _NUMBERS[tokens[i]] < 10:
        value += _NUMBERS[tokens[i]]
        i += 1
    while i < len(tokens) and (tokens[i] in _SCALES or tokens[i] == "dozen"):
        value *= _SCALES.get(tokens[i], 12)
        i += 1
    return value, i


def is_number(token: str) -> bool:
    """Whether a token is a number (``2``, ``2.5``)."""
    return bool(re.fullmatch(r"\d+(?:\.\d+)?", token))


def plural_forms(phrase: str) -> list[str]:
    """English plurals of a phrase's last word (``bookshelf`` -> ``bookshelves``)."""
    *head, last = phrase.split()
    forms: list[str] = []
    if last.endswith(("s", "x", "z", "ch", "sh")):
        forms.append(last + "es")
    elif last.endswith("y") and len(last) > 1 and last[-2] not in "aeiou":
        forms.append(last[:-1] + "ies")
    elif last.endswith("fe"):
        forms += [last[:-2] + "ves", last + "s"]
    elif last.endswith("f"):
        forms += [last[:-1] + "ves", last + "s"]
    elif last.endswith("o"):
        forms += [last + "s", last + "es"]
    else:
        forms.append(last + "s")
    return [" ".join([*head, form]) for form in forms]
