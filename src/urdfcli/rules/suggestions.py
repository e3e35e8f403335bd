"""The "did you mean" hints: the misspelt name with a prefix or suffix it lacks, else the names
closest to it, as :mod:`difflib` ranks them, less those that are the misspelt name with a
whole prefix or suffix cut off (another name), with other numbers (another of a series), or
with whole parts unlike its own (another name sharing a prefix: ``panda_link5`` for ``panda_hand``)."""

from __future__ import annotations

import heapq
from collections.abc import Iterable

from ..read.names import cut_from, numbered_apart, parts_apart


def close_matches(word: str, candidates: Iterable[str], n: int = 1, cutoff: float = 0.6) -> list[str]:
    """``difflib.get_close_matches(word, candidates, n, cutoff)`` over the candidates
    that are not ``word`` cut short (below): the same list, found sooner among many names. difflib scores every candidate that its two cheap
    upper bounds let through; here candidates are scored in the order of the
    tighter bound, and the scoring stops when that bound falls below the n-th best
    score (a robot's names share most of their letters, so many pass the bounds).
    A candidate that is ``word`` with a whole prefix or suffix cut off is never
    offered: for ``robotiq_85_base_link``, ``base_link`` is the robot's base, not the
    gripper's link misspelt; nor one that is ``word`` with other numbers (``link_6`` for
    ``link_7``: another link of the chain), nor one whose parts unlike ``word``'s are
    another name (:func:`~urdfcli.read.names.parts_apart`: ``panda_link5`` for ``panda_hand``). One that is ``word`` with a whole prefix or suffix added
    comes first: ``d500_joint_1`` for ``joint_1`` is a ``${prefix}`` forgotten (difflib
    would rank the other robot's ``joint_u`` above it)."""
    from difflib import SequenceMatcher  # only when a name is misspelt

    candidates = list(candidates)
    extended = sorted((c for c in candidates if cut_from(c, word)), key=lambda c: (len(c), c))  # the least added first
    if extended:
        return extended[:n]
    matcher = SequenceMatcher()
    matcher.set_seq2(word)
    bounded = []
    for candidate in candidates:
        if cut_from(word, candidate) or numbered_apart(word, candidate):
            continue
        matcher.set_seq1(candidate)
        if matcher.real_quick_ratio() >= cutoff:
            bound = matcher.quick_ratio()
            if bound >= cutoff and not parts_apart(word, candidate):
                bounded.append((bound, candidate))
    bounded.sort(key=lambda pair: pair[0], reverse=True)
    best: list[tuple[float, str]] = []  # a heap of the n best (score, name) so far
    for bound, candidate in bounded:
        if len(best) == n and bound < best[0][0]:
            break  # no candidate left can score above the n-th best (an equal score may still win on the name)
        matcher.set_seq1(candidate)
        score = matcher.ratio()
        if score >= cutoff:
            if len(best) < n:
                heapq.heappush(best, (score, candidate))
            elif (score, candidate) > best[0]:
                heapq.heapreplace(best, (score, candidate))
    return [candidate for _, candidate in sorted(best, reverse=True)]
