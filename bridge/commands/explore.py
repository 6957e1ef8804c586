"""`pantarhei explore` (Algorithm 1) and `pantarhei prolog` (an interactive
SWI-Prolog with the theory and the oracle loaded)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError
from pantarhei.theory import defaults

#: How an antecedent's consequent is drawn from its simulations: the modes of
#: bridge/exploration/qualify.py (QUALIFY; named here so that declaring the
#: flag does not import numpy).
QUALIFY = ("weighted", "argmax")


def register(sub: argparse._SubParsersAction) -> None:
    d = defaults()
    p = sub.add_parser("explore", help="learn a theory by curiosity-driven exploration (Algorithm 1)")
    p.add_argument("--max-rules", type=options.count(1, options.MAX_RULES), default=d["max_rules"],
                   help="the budget: this many explored antecedents (paper), the pours of this "
                        f"many batches (discover; default {d['max_rules']})")
    p.add_argument("--samples", type=options.count(1, options.SAMPLES_MAX),
                   help="simulations per explored antecedent (default: parameters + 1)")
    p.add_argument("--curiosity", choices=("discover", "paper"), default=d["curiosity"],
                   help="discover: queue the candidates (moves past where a significant plane's "
                        "verdict flips, neighbours, random jumps) a forest of the pours so far "
                        "predicts to show something new, most novel first; paper: Algorithm 1 "
                        f"as the paper states it (default {d['curiosity']})")
    p.add_argument("--threshold", type=options.number(0),
                   help="discover: the significance level of the permutation test "
                        f"(default {d['significance']}); paper: the plane slope below which "
                        f"nothing new is explored (default {d['threshold']})")
    p.add_argument("--resample", type=options.count(0, options.COUNT_MAX), default=d["resample"],
                   help="discover: more batches of an antecedent whose planes are all undecided "
                        f"(default {d['resample']}); --max-rules then counts batches")
    p.add_argument("--novelty", type=options.number(0, 1), default=d["novelty"],
                   help="discover: the predicted novelty, from 0 to 1, a candidate needs to be "
                        "queued, scaled by the probes' mean score so far "
                        f"(default {d['novelty']})")
    p.add_argument("--queue", type=options.count(1, options.COUNT_MAX), default=d["queue"],
                   help=f"discover: A_new keeps this many most novel candidates (default {d['queue']})")
    p.add_argument("--jumps", type=options.count(1, options.COUNT_MAX), default=d["jumps"],
                   help="discover: uniformly random valid antecedents drawn as candidates each "
                        f"step (default {d['jumps']})")
    p.add_argument("--probe", type=options.count(0, options.SAMPLES_MAX), default=d["probe"],
                   help="discover: simulate this many pours of a candidate's batch first, and "
                        "set it aside for the next when they show no new, reproducible "
                        f"consequent; 0: no probes (default {d['probe']})")
    p.add_argument("--probe-attempts", type=options.count(1, options.COUNT_MAX), default=d["probe_attempts"],
                   help="discover: candidates probed at most in a step; then the one whose "
                        f"probe scored best is explored (default {d['probe_attempts']})")
    p.add_argument("--cover", type=options.count(0, options.COUNT_MAX), default=d["cover"],
                   help="discover: the last probe of a step goes to the candidate whose rarest "
                        "proposition the fewest pours so far hold, when fewer than this many do; "
                        f"0: never (default {d['cover']})")
    p.add_argument("--prior", type=int, choices=(0, 1), default=d["prior"],
                   help="discover: 1 to explore the priors (nothing said: every parameter from "
                        "its prior, as a question's unsaid ones) with the budget's last batch, 0 not to "
                        f"(default {d['prior']})")
    p.add_argument("--permutations", type=options.count(1, options.COUNT_MAX), default=d["permutations"],
                   help=f"discover: shuffles of the permutation test (default {d['permutations']})")
    options.add_seed(p)
    p.add_argument("--initial", metavar="P1,P2,...",
                   help=f"the initial antecedent a_0 (default: {','.join(d['initial'])})")
    p.add_argument("--breadth", type=options.count(1, options.COUNT_MAX), default=d["breadth"],
                   help="modify steps the parameters of this many largest gradient "
                        f"components (default {d['breadth']})")
    p.add_argument("--ridge", type=options.number(0), default=d["ridge"],
                   help="L2 penalty of the plane fits on normalised parameters "
                        f"(default {d['ridge']}; 0 is plain least squares)")
    p.add_argument("--qualify", choices=QUALIFY, default=d["qualify"],
                   help="the consequent of an antecedent: the weighted vote of its simulations "
                        "(weighted) or the simulation of largest weight (argmax, the paper's); "
                        f"default {d['qualify']}")
    options.add_store(p, "simulations and exploration state")
    options.add_theory_out(p, extra="; the trace (.trace.jsonl) and its plot (.trace.png) go beside it")
    p.add_argument("--resume", action="store_true",
                   help="continue the saved exploration with the same settings")
    p.add_argument("--no-general", action="store_true",
                   help="write Algorithm 1's rules only, without the general rules learned "
                        "from every pour")
    options.add_oracle(p)
    options.add_execution(p)
    p.set_defaults(run=explore, pin=True)

    p = sub.add_parser("prolog", help="an interactive SWI-Prolog with the theory and the oracle "
                                      "loaded (try: what_happens([pour_to_side], O).)")
    p.add_argument("--theory", action="append", metavar="FILE",
                   help="theory file, native facts or .dfl (repeat to add hand-written rules; "
                        "default: the shipped learned theory)")
    p.add_argument("--goal", "-g", metavar="GOAL",
                   help="run GOAL (Prolog text) and exit instead of the interactive prompt")
    p.set_defaults(run=prolog, pin=True)     # explore/1 and simulate/3 compute there


def explore(args: argparse.Namespace) -> int:
    from pantarhei.bridge.exploration.loop import Options, explore as run_exploration, stop_text
    from pantarhei.bridge.reasoning import scenes as validity

    from pantarhei.bridge.files import require_writable_file

    require_writable_file(Path(args.out), "--out")
    if args.curiosity == "discover" and args.threshold is not None and args.threshold > 1:
        raise UserError("--threshold is a significance level with --curiosity discover: at most 1")
    initial = None
    if args.initial is not None:
        initial = validity.require_valid([t.strip() for t in args.initial.split(",") if t.strip()])
    opts = Options(
        curiosity=args.curiosity, permutations=args.permutations, resample=args.resample,
        novelty=args.novelty, queue=args.queue, jumps=args.jumps, probe=args.probe,
        probe_attempts=args.probe_attempts, cover=args.cover, prior=args.prior,
        oracle=args.oracle,
        max_rules=args.max_rules, samples=args.samples,
        threshold=args.threshold, seed=args.seed, initial=initial, breadth=args.breadth,
        ridge=args.ridge, qualify=args.qualify, out=Path(args.out), store=Path(args.store),
        resume=args.resume, executor=args.executor, workers=args.workers,
        ray_address=args.ray_address, progress=not args.no_progress,
        general=bool(defaults()["general"]) and not args.no_general)
    try:
        result = run_exploration(opts)
    except KeyboardInterrupt:
        raise UserError("interrupted: the state is saved after every explored antecedent; "
                        "the same command with --resume continues", exit_code=130) from None
    why = stop_text(result, args.curiosity, args.max_rules)
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
    from pantarhei.bridge.reasoning.logic import prolog_load
    from pantarhei.bridge.theories.loading import load
    from pantarhei.theory import prolog_modules
    from pantarhei.bridge.exploration.session import install

    eng = install()
    for name in prolog_modules():
        try:
            eng.use_module(name)
        except UserError as e:  # one module that does not load does not stop the others
            print(f"pantarhei prolog: {name} not loaded: {e}", file=sys.stderr)
    prolog_load(load(args.theory, pouring=True))     # the shipped theory, or the files given
    if args.goal:       # read as a term first: a syntax error is one line
        r = eng.once("catch((term_string(_, T), R = ok), error(syntax_error(S), _), R = S)",
                     T=args.goal)
        if str(r["R"]) != "ok":
            raise UserError(f"--goal: syntax error ({r['R']}) in '{args.goal}'")
        # \+ \+: the goal's bindings stay in Prolog (pyswip cannot read every term back)
        ok = eng.succeeds("\\+ \\+ (term_string(G, T), catch(G, E, (print_message(error, E), fail)))",
                          T=args.goal)
        sys.stdout.flush()
        return 0 if ok else 1
    print("Panta Rhei: the theory and the oracle are loaded. Try\n"
          "  ?- what_happens([pour_to_side], O).\n"
          "  ?- explore([oracle(synthetic), max_rules(5), out('/tmp/learned.pl')]).\n"
          "  ?- sample([pour_to_side], 3, 1, Rows), simulate(Rows, [oracle(synthetic)], Scores).\n"
          "  ?- validity:valid_antecedent([pour_to_side, pour_low]).\n"
          "End with halt. or Ctrl-D.", file=sys.stderr)
    eng.succeeds("prolog")
    return 0
