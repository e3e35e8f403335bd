"""The consumers of URDF urdfcli predicts (``--target NAME``), one package each.

A consumer's package holds one module per layer, so that everything about it is in one
folder and each module still sits in its layer (tests/test_imports.py checks it):

- ``build.py`` (the model layer): the :class:`~urdfcli.model.targets.Consumer` (its
  name, title, code prefix, version followed, variants) and how it builds a model;
- ``rules.py`` (the rules layer): what it refuses, changes and warns about;
- ``load.py`` (the project layer): ``--load``, the real consumer run on the model.

This module is the registry, by name, in the model layer: the list of targets, the
``--target`` help and the docs' list come from it.
"""

from __future__ import annotations

from ..model.load import Loaded
from ..model.targets import Build, Consumer, Profile
from ..read.memo import once
from .drake import build as drake
from .gazebo import build as gazebo
from .isaac import build as isaac
from .kdl import build as kdl
from .mujoco import build as mujoco
from .pinocchio import build as pinocchio
from .pybullet import build as pybullet

TARGETS: dict[str, Consumer] = {module.CONSUMER.name: module.CONSUMER for module in (mujoco, drake, pinocchio, pybullet, gazebo, kdl, isaac)}
ALL = "all"  # every consumer in its default profile


def profile(text: str) -> Profile:
    """``NAME`` or ``NAME:VARIANT[:VARIANT]``; raises ValueError saying what is known."""
    name, *variants = (part.strip().lower() for part in text.split(":"))
    consumer = TARGETS.get(name)
    if consumer is None:
        raise ValueError(f"unknown target '{text}'; the targets are {', '.join(TARGETS)}, or {ALL}")
    for variant in variants:
        if variant not in consumer.variant_names():
            known = ", ".join(f"{name}:{v}" for v in consumer.variant_names()) or "none"
            raise ValueError(f"unknown variant '{variant}' of target {name}; its variants are {known}")
    return Profile(consumer, frozenset(variants))


def profiles(text: str) -> tuple[Profile, ...]:
    """The profiles one ``--target`` value names: ``all`` is every consumer's default."""
    if text.strip().lower() == ALL:
        return tuple(Profile(consumer) for consumer in TARGETS.values())
    return (profile(text),)


def build(loaded: Loaded, chosen: Profile) -> Build:
    """What ``chosen`` builds from the model, worked out once per model."""
    return once(loaded, _build, chosen)


def _build(loaded: Loaded, chosen: Profile) -> Build:
    return chosen.consumer.build(loaded, chosen)


def help_text() -> str:
    """The targets and their variants, as ``--target``'s help lists them."""
    variants = [f"{consumer.name}:{variant.name}" for consumer in TARGETS.values() for variant in consumer.variants]
    return f"{', '.join(TARGETS)}, or {ALL}; variants {', '.join(variants)}"
