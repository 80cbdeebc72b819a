"""Rendering: the camera integral, area lights and path tracing (LECTURE.md §1–3, 8, 9)."""
from __future__ import annotations

__all__: list[str] = []
