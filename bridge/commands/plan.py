"""`pantarhei plan`: how should I pour so that ...? (clingo, verified in
the simulation, learning from the plans it refutes)."""
from __future__ import annotations

import argparse
import json

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError

THEORY_HELP = ("theory file, native facts or .dfl (repeat to add hand-written rules to a learned "
               "theory; default: the shipped learned theory theory/learned/pouring.pl)")


def register(sub: argparse._SubParsersAction) -> None:
    from pantarhei.bridge.reasoning.planning import plan_defaults

    verify, min_success, budget = plan_defaults()
    p = sub.add_parser("plan", help="how to pour to reach a goal? (clingo, verified in the "
                                    "simulation)")
    p.add_argument("context", nargs="?",
                   help='the given context in words, e.g. "pour very high with a light liquid" '
                        "(or --given)")
    p.add_argument("--goal", required=True,
                   help="goal literals G1,G2: expectations, negated as neg(E) or -E; the liquid "
                        "leaving the source is added unless a goal speaks of it (a pour pours)")
    p.add_argument("--given", default="", help="context propositions P1,P2 (liquid, amount, bowls...)")
    p.add_argument("--theory", action="append", metavar="FILE", help=THEORY_HELP)
    p.add_argument("--alternatives", type=options.count(0, options.COUNT_MAX), default=None,
                   metavar="K", help="list up to K plans after the best (default: 4 unverified, "
                                     "0 verified)")
    p.add_argument("--verify", type=options.count(0, options.VERIFY_MAX), default=verify,
                   metavar="N",
                   help=f"simulate N pours of each plan tried, and N fresh ones more of a plan "
                        f"that passes them; a plan is shown only when its goals were met often "
                        f"enough in all of them (default {verify}; 0: show the theory's plans "
                        f"unverified)")
    p.add_argument("--min-success", type=float, default=min_success, metavar="SHARE",
                   help=f"the share of a plan's verifying pours, first the N and then all 2N, "
                        f"that must meet every goal (default {min_success})")
    p.add_argument("--pours", type=options.count(1, options.COUNT_MAX), default=budget,
                   metavar="BUDGET",
                   help=f"pours the search may simulate in all: plans refuted are learned from and "
                        f"the search goes on until a plan is verified or these are spent "
                        f"(default {budget})")
    p.add_argument("--learned-out", metavar="FILE",
                   help="write the theory the search leaves (the theory with the rules learned "
                        "from its pours) to FILE; without it nothing is written")
    p.add_argument("--oracle", choices=options.choices("oracle"), default=None,
                   help="verify with this oracle (default: the one the theory was learned from; "
                        "synthetic: analytic test scores, not a simulation)")
    options.add_seed(p, 0, "--verify's sampling")
    options.add_store(p, "simulations for --verify")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(run=plan, pin=lambda args: args.verify > 0)     # --verify simulates


def _split(text: str | None) -> list[str]:
    return [x.strip() for x in (text or "").split(",") if x.strip()]


def plan(args: argparse.Namespace) -> int:
    from pantarhei.bridge.commands.querying import utf8
    from pantarhei.bridge.reasoning.valid_scenes import known
    from pantarhei.bridge.reasoning.written_theory import as_written
    from pantarhei.bridge.theories import loading

    goals = _split(utf8(args.goal, "--goal"))
    utf8(args.given, "--given")
    if not goals:
        raise UserError("--goal: give at least one goal literal")
    if args.context is not None and args.given.strip():
        raise UserError("give the context in words or with --given, not both")
    if args.context is not None:
        from pantarhei.bridge.reasoning.pattern_store import kept_patterns

        with kept_patterns():
            from pantarhei.bridge.reasoning.reading import understand

            given = known(understand(utf8(args.context, "the context")))
    else:
        given = known(_split(args.given))
    if not 0 < args.min_success <= 1:
        raise UserError("--min-success: a share above 0 and at most 1")
    if args.verify and args.pours < 2 * args.verify:
        raise UserError(f"--pours {args.pours}: the budget must hold one plan's --verify "
                        f"{args.verify} pours and as many confirming them, {2 * args.verify} at least")
    if args.learned_out is not None:
        _require_out(args.learned_out)
    # SWI-Prolog reads the files as written (until the search adds rules to the theory)
    theory = as_written(loading.load(args.theory, pouring=True), args.theory)
    oracle = None
    if args.verify:
        oracle = args.oracle or _verifying_oracle(theory)
        from pantarhei.oracle.base import ORACLES, REAL_ORACLES

        if args.oracle is None and oracle in ORACLES and oracle not in REAL_ORACLES:
            raise UserError(f"{theory.source}: setting(oracle, {oracle}) names a test-only oracle: "
                            f"plans are verified in a real simulation only ({', '.join(REAL_ORACLES)}); "
                            f"--verify 0 shows the theory's plans unverified")
    alternatives = args.alternatives if args.alternatives is not None else (0 if args.verify else 4)
    return print_plans(theory, goals, given, alternatives, args.verify, args.min_success,
                       args.seed, args.store, args.json, budget=args.pours, oracle=oracle,
                       learned_out=args.learned_out)


def _require_out(path: str) -> None:
    from pathlib import Path

    from pantarhei.bridge.files import require_writable_file
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY

    out = Path(path)
    if out.resolve() == Path(DEFAULT_THEORY).resolve():
        raise UserError(f"--learned-out {path}: that is the shipped theory; name another file")
    if not out.parent.is_dir():
        raise UserError(f"--learned-out {path}: no such directory {out.parent}")
    require_writable_file(out, "--learned-out")


def _verifying_oracle(theory) -> str:
    """The oracle a theory's plans are verified with: the one it was
    learned from (its setting(oracle, O)), the default oracle
    (theory/defaults.pl) otherwise."""
    from pantarhei.bridge.theories import loading
    from pantarhei.theory import defaults

    return str((loading.settings(theory).get("oracle") or [defaults()["oracle"]])[0])


def print_plans(theory, goals: list[str], given: list[str], alternatives: int, verify: int,
                min_success: float, seed: int, store, as_json: bool = False, *,
                budget: int | None = None, oracle: str | None = None,
                learned_out: str | None = None) -> int:
    """Print plans for `goals` given `given`, each with its numbers: with
    `verify` pours, the search's verified plans (the best and up to
    `alternatives` more, each met in at least `min_success` of `verify`
    pours and of as many more confirming them, simulated with `oracle` and
    kept in `store`, within `budget` pours in all, the default of
    theory/defaults.pl when None; UserError saying why when none is
    found); with 0, the theory's plans unverified."""
    from pantarhei.bridge.commands.plan_text import plan_json, print_search, print_unverified
    from pantarhei.bridge.reasoning.planning import check_goals, plan as make_plans, pouring_goals

    if not verify:
        lits, added = pouring_goals(goals)
        asked = [g for g in lits if g not in added or _concludes(theory, g)]
        plans = make_plans(theory, check_goals(asked, theory), given, alternatives)
        if as_json:
            print(json.dumps(plan_json(theory, lits, added, given, [(p, None) for p in plans]),
                             indent=1))
            return 0
        print_unverified(theory, lits, added, given, plans)
        return 0
    oracle = oracle or _verifying_oracle(theory)     # the oracle the pours are simulated with
    if budget is None:
        from pantarhei.bridge.reasoning.planning import plan_defaults

        budget = plan_defaults()[2]
    found = _search(theory, goals, given, alternatives, verify, min_success, seed, store, budget,
                    oracle)
    if learned_out is not None and found.learned:
        from pantarhei.bridge.files import write_text

        write_text(learned_out, found.theory.native())
    if not found.verified:
        if as_json:         # the search for a program, and the reason in one line
            print(json.dumps({**plan_json(found.theory, found.goals, found.added, found.given, [],
                                          found, oracle, learned_out), "none": found.reason},
                             indent=1))
        raise UserError(f"no plan found: {found.reason}")
    if as_json:
        print(json.dumps(plan_json(found.theory, found.goals, found.added, found.given,
                                   [(t.plan, t) for t in found.verified], found, oracle,
                                   learned_out), indent=1))
        return 0
    print_search(found, oracle, learned_out)
    return 0


def _concludes(theory, lit: str) -> bool:
    return lit in theory.facts or any(r.head == lit and r.kind != "defeater" for r in theory.rules)


def _search(theory, goals, given, alternatives, verify, min_success, seed, store, budget, oracle):
    from pantarhei.bridge.exploration.simulation import open_simulator, oracle_identity
    from pantarhei.bridge.reasoning.plan_search import search

    oracle_identity(oracle)     # UserError for an oracle that is unknown or cannot load
    with open_simulator(oracle, store=store) as sim:
        return search(theory, goals, given, sim.simulate, verify_pours=verify,
                      min_success=min_success, seed=seed, budget=budget, want=1 + alternatives)
