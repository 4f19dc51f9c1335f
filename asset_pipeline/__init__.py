"""Offline asset processing for holomj: the library writer and the procedural default assets.

This package imports :mod:`holomj.spec`; holomj itself never imports it (except lazily from
the CLI).
"""
