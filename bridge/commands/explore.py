"""`pantarhei explore` (Algorithm 1) and `pantarhei prolog` (an interactive
SWI-Prolog with the theory and the oracle loaded)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .. import exploration, validity
from ..errors import UserError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("explore", help="learn a theory by curiosity-driven exploration (Algorithm 1)")
    p.add_argument("--max-rules", type=int, default=25,
                   help="stop after this many explored antecedents (default 25)")
    p.add_argument("--samples", type=int,
                   help="simulations per explored antecedent (default: parameters + 1 = 31)")
    p.add_argument("--threshold", type=float, default=0.1,
                   help="the plane slope below which nothing new is explored (default 0.1)")
    p.add_argument("--seed", type=int, default=1, help="seed of every random choice (default 1)")
    p.add_argument("--initial", metavar="P1,P2,...",
                   help="the initial antecedent a_0 (default: pour_mid_height,pour_near_rim,"
                        "pour_steeply_tilted)")
    p.add_argument("--breadth", type=int, default=3,
                   help="modify steps the parameters of this many largest gradient "
                        "components (default 3)")
    p.add_argument("--ridge", type=float, default=1.0,
                   help="L2 penalty of the plane fits on normalised parameters "
                        "(default 1.0; 0 is plain least squares)")
    p.add_argument("--qualify", choices=exploration.QUALIFY, default="weighted",
                   help="the consequent of an antecedent: the weighted vote of its simulations "
                        "(default) or the simulation of largest weight (argmax, the paper's)")
    p.add_argument("--store", default=str(exploration.DEFAULT_STORE),
                   help=f"SQLite file of simulations and exploration state "
                        f"(default {exploration.DEFAULT_STORE})")
    p.add_argument("--out", default=str(exploration.DEFAULT_OUT),
                   help="the learned theory (default theory/learned/pouring.pl); the trace "
                        "(.trace.jsonl) and its plot (.trace.png) go beside it")
    p.add_argument("--resume", action="store_true",
                   help="continue the saved exploration with the same settings")
    p.add_argument("--oracle", choices=("pybullet", "synthetic"), default="pybullet",
                   help="the simulation (default pybullet) or analytic test scores")
    p.add_argument("--executor", choices=("local", "ray", "inline"), default="local",
                   help="worker processes here (default), a Ray cluster, or this process")
    p.add_argument("--workers", type=int, help="worker processes (default: one per core)")
    p.add_argument("--ray-address", metavar="ADDR", help="Ray cluster to join (with --executor ray)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(run=explore)

    p = sub.add_parser("prolog", help="an interactive SWI-Prolog with the theory and the oracle "
                                      "loaded (try: explore([oracle(synthetic), max_rules(5)]).)")
    p.add_argument("--goal", "-g", metavar="GOAL",
                   help="run GOAL (Prolog text) and exit instead of the interactive prompt")
    p.set_defaults(run=prolog)


def theory_modules() -> list[str]:
    """The Prolog modules of theory/ (files that start with a module
    declaration), by name."""
    from pantarhei.theory import THEORY_DIR

    names = []
    for path in sorted(THEORY_DIR.glob("*.pl")):
        with open(path, encoding="utf-8") as f:
            head = f.read(200)
        if head.lstrip().startswith(":- module("):
            names.append(path.stem)
    return names


def explore(args: argparse.Namespace) -> int:
    for name in ("max_rules", "samples", "breadth", "workers"):
        v = getattr(args, name)
        if v is not None and v < 1:
            raise UserError(f"--{name.replace('_', '-')} must be at least 1")
    if args.threshold < 0 or args.ridge < 0:
        raise UserError("--threshold and --ridge must not be negative")
    initial = None
    if args.initial is not None:
        initial = validity.require_valid([t.strip() for t in args.initial.split(",") if t.strip()])
    options = exploration.Options(
        oracle=args.oracle, max_rules=args.max_rules, samples=args.samples,
        threshold=args.threshold, seed=args.seed, initial=initial, breadth=args.breadth,
        ridge=args.ridge, qualify=args.qualify, out=Path(args.out), store=Path(args.store),
        resume=args.resume, executor=args.executor, workers=args.workers,
        ray_address=args.ray_address, progress=not args.no_progress)
    try:
        result = exploration.explore(options)
    except KeyboardInterrupt:
        raise UserError("interrupted: the state is saved after every explored antecedent; "
                        "the same command with --resume continues", exit_code=130) from None
    why = {"a_new_empty": "A_new is empty", "max_rules": f"{args.max_rules} rules"}.get(
        result.get("stopped", ""), result.get("stopped", ""))
    print(f"explored {result['explored']} antecedents with {result['simulations']} simulations "
          f"({result['failed']} failed); stopped: {why}")
    wall, sim = result.get("wall", 0.0), result.get("timings", {}).get("oracle", 0.0)
    if wall > 0:
        print(f"time: {wall:.1f} s, simulating {sim:.1f} s, everything else {wall - sim:.1f} s "
              f"({100 * (wall - sim) / wall:.1f}%)")
    print(f"theory: {result['out']}")
    for key in ("trace", "plot"):
        if key in result:
            print(f"{key}: {result[key]}")
    return 0


def prolog(args: argparse.Namespace) -> int:
    eng = exploration.load()
    for name in theory_modules():
        try:
            eng.use_module(name)
        except UserError as e:  # one module that does not load does not stop the others
            print(f"pantarhei prolog: {name} not loaded: {e}", file=sys.stderr)
    if args.goal:
        ok = eng.succeeds(f"catch(({args.goal}), E, (print_message(error, E), fail))")
        sys.stdout.flush()
        return 0 if ok else 1
    print("Panta Rhei: the theory and the oracle are loaded. Try\n"
          "  ?- explore([oracle(synthetic), max_rules(5), out('/tmp/learned.pl')]).\n"
          "  ?- sample([pour_to_side], 3, 1, Rows), simulate(Rows, [oracle(synthetic)], Scores).\n"
          "  ?- validity:valid_antecedent([pour_to_side, pour_low]).\n"
          "End with halt. or Ctrl-D.", file=sys.stderr)
    eng.succeeds("prolog")
    return 0
