"""`pantarhei evaluate`: measure a learned theory against its oracle and
write the report."""
from __future__ import annotations

import argparse
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError, quoted

DEFAULT_REPORT = Path("report")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("evaluate", help="measure a learned theory against its oracle: held-out "
                                        "scenes, a decision tree, random exploration, plans")
    options.add_theory_out(p, "--theory")
    options.add_store(p)
    p.add_argument("--out", default=str(DEFAULT_REPORT),
                   help=f"directory of the report (default {DEFAULT_REPORT}/)")
    p.add_argument("--scenes", type=options.count(1, options.COUNT_MAX), default=150,
                   help="held-out scenes per set, one pour each (default 150)")
    p.add_argument("--verify", type=options.count(0, options.VERIFY_MAX), default=10,
                   help="pours simulated per plan (default 10)")
    p.add_argument("--paper-samples", type=options.count(0, options.VERIFY_MAX), default=20,
                   help="pours simulated per example rule of the paper (default 20)")
    options.add_seed(p)
    p.add_argument("--no-gifs", action="store_true", help="do not render pours as GIFs")
    p.add_argument("--no-baselines", action="store_true",
                   help="do not also spend the budget on random pours from the prior and on "
                        "MAP-Elites (their behaviours seen)")
    options.add_execution(p, progress="no progress bars")
    p.set_defaults(run=evaluate, pin=True)


def _require_apart(theory: Path, store: Path, out: Path) -> None:
    """UserError when the theory, the store or a file of the report (its
    README, evaluation.json, plots and pour GIFs) are one file: the report
    would overwrite what it measures."""
    import re

    from pantarhei.bridge.evaluation.report import FILES
    from pantarhei.bridge.files import require_distinct

    require_distinct({"--theory": theory, "--store": store,
                      **{f"the report's {name}": out / name for name in FILES}})
    for flag, path in (("--theory", theory), ("--store", store)):
        if re.fullmatch(r"pour_a\d+\.gif", path.name) and path.resolve().parent == out.resolve():
            raise UserError(f"{flag} {path}: the report draws its pours as GIFs of that name in "
                            f"{out}: give another path")


#: The record of the files the report wrote in its folder, with their
#: SHA-256: a later report overwrites those alone.
MANIFEST = ".pantarhei-report.json"

#: The first words of the report's README.md: a folder whose README.md
#: begins so, and that has no record yet, holds a report written before
#: the record was kept.
REPORT_HEADING = "# Evaluation of "


def _report_files(out: Path) -> list[Path]:
    """The files of `out` named as the report names its own."""
    import re

    from pantarhei.bridge.evaluation.report import FILES

    if not out.is_dir():
        return []
    return sorted(f for f in out.iterdir()
                  if f.name in FILES or re.fullmatch(r"pour_a\d+\.gif", f.name))


def _digest(path: Path) -> str:
    import hashlib

    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _written_before(out: Path) -> dict[str, str] | None:
    """The files the report wrote in `out` before, name to SHA-256 (None:
    no record; UserError when the record is not the report's)."""
    import json

    record = out / MANIFEST
    if not record.exists():
        return None
    try:
        data = json.loads(record.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        data = None
    if not isinstance(data, dict) or not all(isinstance(v, str) for v in data.values()):
        raise UserError(f"--out {out}: {quoted(MANIFEST)} is not the report's record of its "
                        f"files: give an empty or new folder")
    return data


def _legacy_report(out: Path) -> bool:
    """Does `out` hold a report written before the record was kept?"""
    try:
        with open(out / "README.md", encoding="utf-8") as f:
            return f.readline(200).startswith(REPORT_HEADING)
    except (OSError, UnicodeDecodeError):
        return False


def require_own(out: Path) -> None:
    """UserError, before anything is measured, when `out` holds a file the
    report would write over that it did not write itself (or changed since):
    a person's README.md, a project's folder. Other files are left as they
    are."""
    before = _written_before(out)
    legacy = before is None and _legacy_report(out)
    for f in _report_files(out):
        if legacy or (before is not None and before.get(f.name) == _digest(f)):
            continue
        raise UserError(f"--out {out}: {quoted(f.name)} was not written by a report (or was "
                        f"changed since): the report would replace it; give an empty or new "
                        f"folder")


def record_own(out: Path) -> None:
    """Record the files of the report in `out` (MANIFEST), after writing it."""
    import json

    from pantarhei.bridge.files import write_text

    write_text(out / MANIFEST, json.dumps({f.name: _digest(f) for f in _report_files(out)},
                                          indent=1, sort_keys=True) + "\n")


def evaluate(args: argparse.Namespace) -> int:
    from pantarhei.bridge.evaluation.pipeline import EvaluationOptions, evaluate as run
    from pantarhei.bridge.evaluation.headline import headline
    from pantarhei.bridge.evaluation.report import write
    from pantarhei.bridge.files import require_writable_file

    theory = Path(args.theory)
    if not theory.is_file():
        raise UserError(f"{theory}: no such theory (learn one with `pantarhei explore`)")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise UserError(f"{out}: not a directory")
    require_writable_file(out / "evaluation.json", "--out")
    _require_apart(theory, Path(args.store), out)
    require_own(out)
    ev = run(EvaluationOptions(theory=theory, store=Path(args.store), scenes=args.scenes, seed=args.seed,
                     verify=args.verify, paper_samples=args.paper_samples,
                     executor=args.executor, workers=args.workers,
                     ray_address=args.ray_address, progress=not args.no_progress,
                     baselines=not args.no_baselines))
    report = write(ev, out, gifs=not args.no_gifs)
    record_own(out)
    for measure, value, target, met in headline(ev):
        print(f"{'  ' if met else '! '}{measure}: {value} (target {target})")
    print(f"report: {report}")
    return 0
