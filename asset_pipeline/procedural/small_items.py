"""Generators of small items categories (filled in by the category work of issue 15)."""

from __future__ import annotations
