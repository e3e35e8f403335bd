"""Rules about suppression comments themselves (reported by ``urdfcli lint``)."""

from ..diagnostics import Severity
from .base import Kind, RuleSet, declare, explain

INFO, WARNING = Severity.INFO, Severity.WARNING

U001 = declare("U001", "unused-suppression", INFO, "A `urdfcli: noqa` comment that silences nothing.", explain(
    "Reports a code, prefix or rule name in a `<!-- urdfcli: noqa: CODE -->` or `noqa-file` comment when it silenced no diagnostic, and a bare `noqa` that silenced nothing on its element.",
    "A stale suppression hides the next real problem of that kind on that element, and misleads readers about what is wrong there.",
    '<!-- urdfcli: noqa: D002 -->\n<link name="base_link"/>',
    '<link name="base_link"/>'), kind=Kind.SUPPRESSIONS, rule_set=RuleSet.LINT)
U002 = declare("U002", "suppression-code-unknown", WARNING, "A `urdfcli: noqa` comment names no rule.", explain(
    "Reports a word in a suppression comment that is neither a rule's code, nor a prefix of codes, nor a rule's name.",
    "The comment silences nothing; the problem it was meant for is still reported, or the code is a typo.",
    '<!-- urdfcli: noqa: D02 -->\n<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><metrial/></visual>\n</link>',
    '<link name="base_link">\n  <visual><geometry><box size="1 1 1"/></geometry><material name="grey"><color rgba="0.5 0.5 0.5 1"/></material></visual>\n</link>'), kind=Kind.SUPPRESSIONS, rule_set=RuleSet.LINT)
