"""`pantarhei demo`: the main job on the embedded defaults.

Learn the theory of pouring by curious exploration of the PyBullet
simulation (the pours of 25 batches, the paper's scale), write it natively
and in DFL, then ask it the paper's three questions and one goal query. Simulations are
stored, so a second run simulates nothing.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError
from pantarhei.theory import defaults
from pantarhei.theory.option_table import option

#: The paper's three questions (section 3.2), as words and propositions.
QUESTIONS = (
    ("What happens if I pour from the side?", ["pour_to_side"]),
    ("What happens if the liquid is very light?", ["light_liquid"]),
    ("What happens if I pour a light liquid and right the source up low above the destination?",
     ["light_liquid", "end_upright", "end_low"]),
)
#: The goal query: a clean pour, in which the liquid ends up in the destination.
GOAL = "liquid_leaves_source,liquid_remains_in_destination,no_spill"


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("demo", help="the main job: learn the theory of pouring (PyBullet, the "
                                    "pours of 25 batches), write it, ask it the paper's "
                                    "questions and plan")
    options.add_oracle(p)
    options.add_table_option(p, option("budget"))    # as explore's
    options.add_seed(p)
    options.add_theory_out(p, extra="; the DFL version goes beside it as .dfl")
    options.add_store(p)
    p.add_argument("--verify", type=options.count(0, options.VERIFY_MAX), default=10,
                   help="pours simulated to check the plan (default 10; 0: none)")
    options.add_workers(p)
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(run=demo, pin=True)


def _heading(text: str) -> None:
    print(f"\n== {text}", flush=True)


def demo(args: argparse.Namespace) -> int:
    from pantarhei.bridge.theories.dfl import write_dfl
    from pantarhei.bridge.files import require_writable_file, write_text
    from pantarhei.bridge.theories import loading
    from pantarhei.bridge.commands.explore import require_distinct_outputs
    from pantarhei.bridge.commands.querying import answer, print_plans
    from pantarhei.bridge.exploration.running import Options, budget_text, explore, stop_text

    out = Path(args.out)
    require_writable_file(out, "--out")
    require_distinct_outputs(Path(args.store), out, dfl=True)
    started = time.monotonic()
    curiosity = defaults()["curiosity"]
    _heading(f"Learning the theory of pouring: curious exploration of the {args.oracle} "
             f"simulation, {budget_text(curiosity, args.budget)} (Algorithm 1)")
    result = explore(Options(
        oracle=args.oracle, budget=args.budget, seed=args.seed, out=out,
        store=Path(args.store), workers=args.workers, progress=not args.no_progress))
    theory = loading.load([out], pouring=True)      # read once, for every question below
    dfl = out.with_suffix(".dfl")
    write_text(dfl, write_dfl(theory, loading.provenance_lines(theory)))
    why = stop_text(result, curiosity, args.budget)
    print(f"explored {result['explored']} antecedents with {result['simulations']} simulations "
          f"({result['failed']} failed) in {result.get('wall', 0.0):.0f} s; stopped: {why}")
    print(f"theory: {out} ({len(theory.rules)} rules), in DFL: {dfl}")
    if "plot" in result:
        print(f"exploration trace: {result['trace']}, plot: {result['plot']}")

    for question, props in QUESTIONS:
        _heading(question)
        answer(theory, props)

    _heading(f"How should I pour so that {GOAL.replace(',', ', ')}?")
    try:
        print_plans(theory, GOAL.split(","), [], alternatives=2, verify=args.verify,
                    min_success=0.9, seed=args.seed, store=args.store)
    except UserError as e:     # a theory that cannot reach the goal: say so, and finish
        print(f"no plan: {e}")
    print(f"\ndone in {time.monotonic() - started:.0f} s. Ask more: pantarhei ask \"pour high "
          f"above the destination\"; plan: pantarhei plan --goal no_spill; "
          f"measure it: make evaluate")
    return 0
