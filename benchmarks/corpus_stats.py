"""Warnings per published model, before and after: the figures of the README's
"Precision on published robots" section.

After: the reviewed snapshot tests/snapshots/example-robot-data.txt (regenerate
it first: ``URDFCLI_UPDATE_SNAPSHOTS=1 pytest tests/test_corpus.py``).
Before: benchmarks/corpus_before.txt, counts per model and code of an earlier
urdfcli, written from its ``urdfcli lint --format json`` report with

    python benchmarks/corpus_stats.py --write-before REPORT.json

Mesh findings (D004, D005) are counted apart: the earlier run did not resolve
the corpus's ``package://example-robot-data`` URIs, so every mesh was reported.

    python benchmarks/corpus_stats.py
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SNAPSHOT = ROOT / "tests" / "snapshots" / "example-robot-data.txt"
BEFORE = ROOT / "benchmarks" / "corpus_before.txt"
MESH = {"D004", "D005"}
LINE = re.compile(r"^(?P<model>[^:]+\.urdf):\d+: (?P<code>[A-Z]\d{3}) (?P<severity>\w+): ")


def model_of(path: str) -> str:
    """A model's path relative to the corpus's robots folder."""
    return path.split("/robots/", 1)[1] if "/robots/" in path else path


def write_before(report: Path) -> None:
    counts: Counter = Counter()
    models = set()
    for file in json.loads(report.read_text())["files"]:
        model = model_of(file["path"])
        models.add(model)
        for d in file["diagnostics"]:
            if d["severity"] in ("error", "warning"):
                counts[(model, d["code"], d["severity"])] += 1
    lines = [f"{model} - - 0" for model in sorted(models)]  # every model, even one with no finding
    lines += [f"{model} {code} {severity} {n}" for (model, code, severity), n in sorted(counts.items())]
    BEFORE.write_text(f"# MODEL CODE SEVERITY COUNT, from {report.name}\n" + "\n".join(lines) + "\n")


def read_before() -> tuple[list[str], Counter]:
    models, counts = [], Counter()
    for line in BEFORE.read_text().splitlines():
        if line.startswith("#"):
            continue
        model, code, severity, n = line.split()
        if code == "-":
            models.append(model)
        else:
            counts[(model, code, severity)] += int(n)
    return models, counts


def read_after() -> Counter:
    counts: Counter = Counter()
    for line in SNAPSHOT.read_text().splitlines():
        match = LINE.match(line)
        if match:
            counts[(match["model"], match["code"], match["severity"])] += 1
    return counts


def per_model(models: list[str], counts: Counter, severity: str, mesh: bool) -> dict[str, int]:
    return {m: sum(n for (model, code, s), n in counts.items() if model == m and s == severity and (code in MESH) == mesh) for m in models}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write-before", type=Path, metavar="REPORT.json", help="write benchmarks/corpus_before.txt from a lint JSON report")
    args = parser.parse_args()
    if args.write_before:
        write_before(args.write_before)
        return 0
    models, before = read_before()
    after = read_after()
    rows = []
    for name, counts in (("before", before), ("after", after)):
        warnings = per_model(models, counts, "warning", mesh=False)
        mesh = per_model(models, counts, "warning", mesh=True)
        errors = per_model(models, counts, "error", mesh=False)
        values = list(warnings.values())
        rows.append((name, statistics.median(values), max(values), sum(values), sum(1 for v in values if v == 0), sum(mesh.values()), sum(errors.values())))
    print(f"{len(models)} models of example-robot-data\n")
    print("| | median warnings per model | most | total | models without warnings | mesh warnings (D004, D005) | errors |")
    print("|---|---|---|---|---|---|---|")
    for row in rows:
        print("| " + " | ".join(str(v) for v in row) + " |")
    print("\nWarnings by rule (mesh warnings apart):\n")
    print("| rule | before | after |")
    print("|---|---|---|")
    codes = sorted({code for (_, code, s) in list(before) + list(after) if s == "warning"})
    for code in codes:
        b = sum(n for (_, c, s), n in before.items() if c == code and s == "warning")
        a = sum(n for (_, c, s), n in after.items() if c == code and s == "warning")
        print(f"| {code} | {b} | {a} |")
    print("\nMost warnings after (mesh warnings apart):\n")
    after_warnings = per_model(models, after, "warning", mesh=False)
    before_warnings = per_model(models, before, "warning", mesh=False)
    for model in sorted(models, key=lambda m: -after_warnings[m])[:10]:
        print(f"- {model}: {before_warnings[model]} -> {after_warnings[model]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
