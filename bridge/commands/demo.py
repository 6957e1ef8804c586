"""`pantarhei demo`: the main job on the embedded defaults.

Learn the theory of pouring by curious exploration of the PyBullet
simulation (the project's curiosity and budget: every pour counted),
write it natively and in DFL, then ask it the paper's three questions and
plan a pour whose goals the ordinary pour does not reach, checked in
simulation. Simulations are stored, so a second run simulates nothing.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError
from pantarhei.theory.option_table import option

#: The paper's three questions (section 3.2), as words and propositions.
QUESTIONS = (
    ("What happens if I pour from the side?", ["pour_to_side"]),
    ("What happens if the liquid is very light?", ["light_liquid"]),
    ("What happens if I pour a light liquid and right the source up low above the destination?",
     ["light_liquid", "end_upright", "end_low"]),
)
#: The goal queries, as a person would ask them: what is given, and the
#: goals. The demo plans the first whose goals the theory says the ordinary
#: pour with what is given does not reach and some manner of pouring does
#: (the last, a clean pour, when there is none).
PLANS = (
    (["light_liquid"], "liquid_leaves_source"),
    (["pour_to_side"], "liquid_enters_destination,no_spill"),
    (["heavy_liquid", "light_destination"], "destination_upright,no_spill"),
    (["pour_low"], "source_clear,destination_still_approach"),
    ([], "liquid_leaves_source,liquid_remains_in_destination,no_spill"),
)


def chosen_plan(theory) -> tuple[list[str], list[str], bool]:
    """The goal query of PLANS the demo asks: what is given, the goals, and
    whether the ordinary pour with what is given misses them (as the
    theory answers it) while a plan reaches them."""
    from pantarhei.bridge.reasoning.answers import what_happens
    from pantarhei.bridge.reasoning.planning import parse_goal, plan

    for given, goal in PLANS:
        goals = [parse_goal(g) for g in goal.split(",")]
        said = {a.expectation: a.value for a in what_happens(theory, given)}
        if all(said.get(g) == "holds" for g in goals):
            continue
        try:
            if plan(theory, goals, given, alternatives=1):
                return given, goals, True
        except UserError:       # no manner of pouring reaches them
            continue
    given, goal = PLANS[-1]
    return given, goal.split(","), False


def register(sub: argparse._SubParsersAction) -> None:
    from pantarhei.bridge.reasoning.planning import plan_defaults

    p = sub.add_parser("demo", help="the main job: learn the theory of pouring (PyBullet, "
                                    "every pour counted), write it, ask it the paper's "
                                    "questions and plan a pour the ordinary pour fails")
    options.add_oracle(p)
    options.add_table_option(p, option("pours"))     # as explore's
    options.add_seed(p)
    p.add_argument("--out", default=None,
                   help=f"the learned theory (default {options._shown(options.DEFAULT_THEORY)}, "
                        f"the shipped theory, which the default oracle, pours and seed write "
                        f"again; with others {option('out').default}); the DFL version goes "
                        f"beside it as .dfl")
    options.add_store(p)
    verify = plan_defaults()[0]
    p.add_argument("--verify", type=options.count(0, options.VERIFY_MAX), default=verify,
                   help=f"pours simulated to check the plan, and as many to confirm it "
                        f"(default {verify}; 0: none)")
    options.add_workers(p)
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(run=demo, pin=True)


def default_out(args: argparse.Namespace) -> Path:
    """Where the demo writes its theory when not told: the shipped theory
    for the run that writes it again (the default oracle, pours and seed),
    else where an exploration writes by default, so that a smaller or
    synthetic run never replaces the shipped theory."""
    from pantarhei.theory import defaults

    shipped = (args.oracle == defaults()["oracle"] and args.pours == option("pours").default
               and args.seed == int(defaults()["seed"]))
    return options.DEFAULT_THEORY if shipped else Path(str(option("out").default))


def _heading(text: str) -> None:
    print(f"\n== {text}", flush=True)


def demo(args: argparse.Namespace) -> int:
    from pantarhei.bridge.theories.dfl import write_dfl
    from pantarhei.bridge.files import require_writable_file, write_text
    from pantarhei.bridge.theories import loading
    from pantarhei.bridge.exploration.trace import require_distinct_outputs
    from pantarhei.bridge.commands.plan import print_plans
    from pantarhei.bridge.reasoning.planning import plan_defaults
    from pantarhei.bridge.commands.querying import answer
    from pantarhei.bridge.reasoning.answers import InProcess
    from pantarhei.bridge.reasoning.written_theory import as_written
    from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore, stop_text

    out = Path(args.out) if args.out is not None else default_out(args)
    require_writable_file(out, "--out")
    require_distinct_outputs(Path(args.store), out, dfl=True)
    started = time.monotonic()
    # the default curiosity, whose budget is every pour (--pours)
    _heading(f"Learning the theory of pouring: curious exploration of the {args.oracle} "
             f"simulation, {args.pours} pours (Algorithm 1)")
    result = explore(ExploreOptions(
        oracle=args.oracle, pours=args.pours, seed=args.seed, out=out,
        store=Path(args.store), workers=args.workers, progress=not args.no_progress))
    # read once, for every question below; SWI-Prolog reads the file as written
    theory = as_written(loading.load([out], pouring=True), [out])
    dfl = out.with_suffix(".dfl")
    write_text(dfl, write_dfl(theory, loading.provenance_lines(theory)))
    why = stop_text(result)
    print(f"explored {result['explored']} antecedents with {result['simulations']} simulations "
          f"({result['failed']} failed) in {result.get('wall', 0.0):.0f} s; stopped: {why}")
    print(f"theory: {out} ({len(theory.rules)} rules), in DFL: {dfl}")
    if "plot" in result:
        print(f"exploration trace: {result['trace']}, plot: {result['plot']}")

    for question, props in QUESTIONS:
        _heading(question)
        answer(InProcess(theory), props)

    given, goals, missed = chosen_plan(theory)
    _heading(f"How should I pour so that {', '.join(goals)}"
             + (f", given {', '.join(given)}?" if given else "?"))
    print("the ordinary pour" + (f" with {', '.join(given)}" if given else "")
          + (" does not reach these goals, as the theory says" if missed
             else " already reaches these goals, as the theory says"))
    try:
        print_plans(theory, goals, given, alternatives=2, verify=args.verify,
                    min_success=plan_defaults()[1], seed=args.seed, store=args.store)
    except UserError as e:     # a theory that cannot reach the goal: say so, and finish
        print(f"no plan: {e}")
    print(f"\ndone in {time.monotonic() - started:.0f} s. Ask more: pantarhei ask \"pour high "
          f"above the destination\"; plan: pantarhei plan --goal no_spill; "
          f"measure it: make evaluate")
    return 0
