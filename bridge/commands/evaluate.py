"""`pantarhei evaluate`: measure a learned theory against its oracle and
write the report."""
from __future__ import annotations

import argparse
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError

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
    ev = run(EvaluationOptions(theory=theory, store=Path(args.store), scenes=args.scenes, seed=args.seed,
                     verify=args.verify, paper_samples=args.paper_samples,
                     executor=args.executor, workers=args.workers,
                     ray_address=args.ray_address, progress=not args.no_progress,
                     baselines=not args.no_baselines))
    report = write(ev, out, gifs=not args.no_gifs)
    for measure, value, target, met in headline(ev):
        print(f"{'  ' if met else '! '}{measure}: {value} (target {target})")
    print(f"report: {report}")
    return 0
