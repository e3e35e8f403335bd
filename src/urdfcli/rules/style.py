"""Naming style rules: off by default, configurable (``[tool.urdfcli.options.CODE]``)."""

from __future__ import annotations

import re
from fnmatch import fnmatchcase

from .base import WARNING, Option, RuleSet, check

SNAKE_CASE = re.compile(r"[a-z][a-z0-9]*(_[a-z0-9]+)*")
FRAME_EXEMPTIONS = ["base_footprint", "world", "*_frame", "*_optical_frame"]


def _exempt(name: str, patterns) -> bool:
    return any(fnmatchcase(name, pattern) for pattern in patterns)


def _suffix_rule(loaded, code: str, kind: str, names: dict, options: dict):
    suffix = options["suffix"]
    for name, item in names.items():
        if name and not name.endswith(suffix) and not _exempt(name, options["exempt"]):
            yield loaded.diagnostic(code, f"{kind} name '{name}' does not end in '{suffix}'", item.at, f"rename it '{name}{suffix}', or add it to the rule's 'exempt' option")


@check(
    "S001", "link-name-suffix", WARNING, "A link name that does not end in the link suffix (`_link`).",
    rule_set=RuleSet.LINT, default=False,
    options=(
        Option("suffix", "_link", "The suffix every link name ends in."),
        Option("exempt", FRAME_EXEMPTIONS, "Glob patterns of link names that need no suffix."),
    ),
)
def link_name_suffix(loaded, given):
    """## What it does
    Flags a link whose name does not end in `_link` (option `suffix`), except
    names matching the `exempt` patterns (by default `base_footprint`, `world`,
    `*_frame`, `*_optical_frame`: frames by convention).

    ## Why is this bad?
    A shared naming convention tells links from joints in TF trees, launch
    files and controller configurations at a glance (REP 120 style).

    ## Example
    ```xml
    <link name="arm"/>
    ```

    ## Use instead
    ```xml
    <link name="arm_link"/>
    ```
    """
    yield from _suffix_rule(loaded, "S001", "link", loaded.robot.links, given.options)


@check(
    "S002", "joint-name-suffix", WARNING, "A joint name that does not end in the joint suffix (`_joint`).",
    rule_set=RuleSet.LINT, default=False,
    options=(
        Option("suffix", "_joint", "The suffix every joint name ends in."),
        Option("exempt", [], "Glob patterns of joint names that need no suffix."),
    ),
)
def joint_name_suffix(loaded, given):
    """## What it does
    Flags a joint whose name does not end in `_joint` (option `suffix`), except
    names matching the `exempt` patterns.

    ## Why is this bad?
    Joint names appear in controller configurations, MoveIt groups and joint
    state topics; a suffix keeps them apart from the links they connect.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="shoulder" type="fixed">
      <parent link="base_link"/>
      <child link="arm_link"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="shoulder_joint" type="fixed">
      <parent link="base_link"/>
      <child link="arm_link"/>
    </joint>
    ```
    """
    yield from _suffix_rule(loaded, "S002", "joint", loaded.robot.joints, given.options)


@check(
    "S003", "name-not-snake-case", WARNING, "A link, joint or material name that is not snake_case.",
    rule_set=RuleSet.LINT, default=False,
    options=(Option("exempt", [], "Glob patterns of names that need not be snake_case."),),
)
def name_not_snake_case(loaded, given):
    """## What it does
    Flags link, joint and material names that are not snake_case (lower-case
    letters and digits, words joined by single underscores), except names
    matching the `exempt` patterns.

    ## Why is this bad?
    ROS names are snake_case; mixed styles make TF frames and parameters hard
    to type and to search, and some tools reject names with spaces or dashes.

    ## Example
    ```xml
    <link name="LeftWheel"/>
    ```

    ## Use instead
    ```xml
    <link name="left_wheel"/>
    ```
    """
    robot = loaded.robot
    for kind, names in (("link", robot.links), ("joint", robot.joints), ("material", robot.materials)):
        for name, item in names.items():
            if name and not SNAKE_CASE.fullmatch(name) and not _exempt(name, given.options["exempt"]):
                yield loaded.diagnostic("S003", f"{kind} name '{name}' is not snake_case", item.at)
