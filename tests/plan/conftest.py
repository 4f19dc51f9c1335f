"""Fixtures of the planner tests: one text encoder for the whole session (loading takes ~10 s)."""

from __future__ import annotations

import pytest

from holomj.plan.knowledge import knowledge_base
from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.retrieval.text import TextEncoder


@pytest.fixture(scope="session")
def encoder() -> TextEncoder:
    """The default text encoder (all-MiniLM-L6-v2 from its package), loaded once."""
    from holomj.retrieval.text import text_encoder

    return text_encoder()


@pytest.fixture(scope="session")
def kb() -> KnowledgeBase:
    """The shipped knowledge base."""
    return knowledge_base()
