"""The "did you mean" search gives difflib's answer, with less of its work."""

from __future__ import annotations

import difflib

from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.rules.suggestions import close_matches

NAMES = st.text(alphabet="abcde_12", max_size=8)  # few letters: many ties and near misses


@settings(max_examples=2000, deadline=None)
@given(NAMES, st.lists(NAMES, max_size=30), st.integers(1, 4), st.sampled_from([0.0, 0.3, 0.6, 0.8]))
def test_the_same_names_as_difflib(word, candidates, n, cutoff):
    assert close_matches(word, candidates, n, cutoff) == difflib.get_close_matches(word, candidates, n, cutoff)


def test_a_misspelt_link_among_many():
    links = [f"{side}_{part}_link" for side in ("left", "right") for part in ("shoulder", "elbow", "wrist", "finger", "thumb", "palm")]
    assert close_matches("left_elbw_link", links) == ["left_elbow_link"]
    assert close_matches("left_elbw_link", links, n=3) == difflib.get_close_matches("left_elbw_link", links, n=3)
