"""Each source file is read once and parsed once per run, and once per edit in the editor:
the expansion, the rules, the outline, the fixes and the excerpts share one object per
file (xacro's own parse, in its worker, is the only other reader)."""

from __future__ import annotations

import os

from conftest import FIXTURES

from urdfcli import api
from urdfcli.options import Options, RuleSet
from urdfcli.session import Session

CAR = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"


def keys(*files) -> set[str]:
    return {os.path.abspath(f) for f in files}


def test_check_and_lint_read_and_parse_each_source_once():
    for rule_set in (RuleSet.CHECK, RuleSet.LINT):
        with Session(Options(rule_set)) as session:
            [result] = api.run([str(CAR)], session).results
            files = session.files
            sources = keys(CAR, *result.includes)  # the model and the four files it includes
            assert len(sources) == 5
            assert dict(files.reads) == dict.fromkeys(sources, 1)
            assert dict(files.parses) == dict.fromkeys(sources, 1)
            read, parsed = dict(files.reads), dict(files.parses)
            api.run([str(CAR)], session)  # nothing changed on disk: nothing read or parsed again
            assert (dict(files.reads), dict(files.parses)) == (read, parsed)


def test_a_plain_urdf_is_read_and_parsed_once_by_the_reader_and_the_rules():
    model = FIXTURES / "seed000" / "my_robot.urdf"
    with Session(Options(RuleSet.LINT)) as session:
        api.run([str(model)], session)
        assert dict(session.files.reads) == {str(model): 1}
        assert dict(session.files.parses) == {str(model): 1}


def test_an_edit_is_parsed_once_by_the_check_and_the_outline():
    """The editor's two threads, the checks and the requests, read one object per buffer."""
    from urdfcli.lsp.engine import Checker, Navigator

    checker = Checker()
    navigator = Navigator((), checker.session.files)
    try:
        path = str(CAR)
        text = CAR.read_text()
        for edit in range(3):
            text = text.replace("</robot>", f"<!-- edit {edit} -->\n</robot>")
            checker.check(path, {path: text})
            navigator.sync({path: text})
            assert navigator.outline(path) is not None
            navigator.hover(path, 1, 1)
            assert checker.session.files.parses[path] == edit + 1
            assert path not in checker.session.files.reads  # the editor's text, never the file on disk
    finally:
        checker.close()


def test_a_large_urdf_beside_a_library_is_read_once_by_its_edits(tmp_path):
    """An edit of a library looks across the repository for the models that include it;
    a URDF too large to keep in memory is not read again for that at every edit."""
    from urdfcli.lsp.engine import Checker

    (tmp_path / ".git").mkdir()
    (tmp_path / "package.xml").write_text('<package format="3"><name>arm_description</name></package>\n')
    library = tmp_path / "arm.xacro"
    library.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                       '  <xacro:macro name="arm"><link name="arm"/></xacro:macro>\n</robot>\n')
    (tmp_path / "robot.urdf.xacro").write_text('<robot name="robot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                               '  <xacro:include filename="arm.xacro"/>\n  <xacro:arm/>\n</robot>\n')
    large = tmp_path / "generated.urdf"
    links = "".join(f'  <link name="l{i}"/>\n' for i in range(60_000))
    large.write_text(f'<robot name="generated">\n{links}</robot>\n')
    assert large.stat().st_size > 1 << 20  # not kept in memory between checks
    checker = Checker()
    try:
        path, text = str(library), library.read_text()
        for edit in range(3):
            text = text.replace("</robot>", f"<!-- edit {edit} -->\n</robot>")
            checked = checker.check(path, {path: text})
            assert checked is not None
        assert checker.session.files.reads[str(large)] == 1
    finally:
        checker.close()
