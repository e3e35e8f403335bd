"""A name written where another was meant: the misspelling of a known name, by edits."""

from __future__ import annotations

import os
import re
from collections.abc import Iterable


def typo_of(word: str, candidates: Iterable[str]) -> str | None:
    """The candidate ``word`` is a misspelling of: one edit away (two for longer words), case aside."""
    allowed = 1 if len(word) <= 4 else 2
    scored = sorted((_edits(word.lower(), c.lower()), c) for c in candidates if not cut_from(word, c) and not numbered_apart(word, c))
    return scored[0][1] if scored and scored[0][0] <= allowed else None


def cut_from(word: str, candidate: str) -> bool:
    """Whether ``candidate`` is ``word`` with a whole prefix or suffix cut off, at a
    separator (``base_link`` of ``robotiq_85_base_link``, ``arm`` of ``arm_2``), case
    aside: another name, which a "did you mean" hint must not offer for a typo. A cut
    part that the candidate repeats is a prefix written twice, a mistake the hint is
    for (``double_stereo_link`` of ``double_stereo_double_stereo_link``)."""
    word, candidate = word.lower(), candidate.lower()
    if not candidate or len(candidate) >= len(word):
        return False
    if word.endswith(candidate):
        cut = len(word) - len(candidate)
        doubled = candidate.startswith(word[:cut])
    elif word.startswith(candidate):
        cut = len(candidate)
        doubled = candidate.endswith(word[cut:])
    else:
        return False
    return (not word[cut - 1].isalnum() or not word[cut].isalnum()) and not doubled


def parts_apart(word: str, candidate: str) -> bool:
    """Whether ``candidate`` shares whole parts with ``word`` (between separators) and
    writes another part where ``word`` writes one unlike it: another name, however much
    the two share, which a "did you mean" hint must not offer for a typo (``panda_link5``
    for ``panda_hand``, ``right_elbow_link`` for ``left_elbw_link``). A part added or
    left out is not that (``sensor_mount_link`` for ``sensor_mount_sensor_link``: a
    macro's prefix written twice). Case aside."""
    from difflib import SequenceMatcher  # only when a name is misspelt

    ours, theirs = _parts(word), _parts(candidate)
    steps = SequenceMatcher(None, ours, theirs, autojunk=False).get_opcodes()
    if not any(step == "equal" for step, *_ in steps):
        return False  # nothing whole in common: difflib's score says it all
    for step, i, j, k, m in steps:
        if step != "replace":
            continue
        pairs = zip(ours[i:j], theirs[k:m]) if j - i == m - k else [("_".join(ours[i:j]), "_".join(theirs[k:m]))]
        if any(SequenceMatcher(None, one, other).ratio() < 0.6 for one, other in pairs):  # (difflib's own cutoff)
            return True
    return False


def _parts(name: str) -> list[str]:
    return [part for part in re.split(r"[^0-9a-z]+", name.lower()) if part]


def numbered_apart(word: str, candidate: str) -> bool:
    """Whether ``candidate`` differs from ``word`` only where one of them has a number
    (``link_6`` or ``link_ee`` for ``link_7``, ``A2`` for ``A1``), case aside: another
    member of a numbered series, which a "did you mean" hint must not offer for a typo
    (the user renamed or lost that one)."""
    word, candidate = word.lower(), candidate.lower()
    start = len(os.path.commonprefix([word, candidate]))
    end = len(os.path.commonprefix([word[start:][::-1], candidate[start:][::-1]]))
    return any(middle.isdigit() for middle in (word[start : len(word) - end], candidate[start : len(candidate) - end]))


def _edits(a: str, b: str) -> int:
    """Edits (insertion, deletion, substitution, swap of neighbours) from a to b."""
    previous, current = None, list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        before, previous, current = previous, current, [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cost = a[i - 1] != b[j - 1]
            current[j] = min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost)
            if before is not None and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                current[j] = min(current[j], before[j - 2] + 1)
    return current[len(b)]


__all__ = ["cut_from", "numbered_apart", "typo_of"]
