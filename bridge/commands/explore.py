"""`pantarhei explore` (Algorithm 1) and `pantarhei prolog` (an interactive
SWI-Prolog with the theory and the oracle loaded)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("explore", help="learn a theory by curiosity-driven exploration (Algorithm 1)",
                       description="Every option is in the option table (theory/defaults.pl, "
                                   "and a curiosity's module for its own: docs/options.md); "
                                   "those that tune the discovering and the "
                                   "paper's curiosity are options of explore/1 at the Prolog "
                                   "prompt (pantarhei prolog).")
    add_flags(p)
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
    from pantarhei.bridge.exploration.explore_call import (ExploreOptions, stop_text,
                                                           explore as run_exploration)
    from pantarhei.bridge.exploration.trace import require_distinct_outputs
    from pantarhei.bridge.files import require_writable_file

    require_writable_file(Path(args.out), "--out")
    require_distinct_outputs(Path(args.store), Path(args.out))
    opts = ExploreOptions(**option_values(args))
    try:
        result = run_exploration(opts)
    except KeyboardInterrupt:
        raise UserError("interrupted: the state is saved after every explored antecedent; "
                        "the same command with --resume continues", exit_code=130) from None
    why = stop_text(result)
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


def add_flags(p: argparse.ArgumentParser, every: bool = False) -> None:
    """explore's flags: one per row of the option table that the command
    line offers (`command_line_options`), or with `every`, one per row
    (for a benchmark that sets the Prolog-only options as flags)."""
    from pantarhei.theory.option_table import command_line_options, option_table

    for o in option_table() if every else command_line_options():
        options.add_table_option(p, o)


def option_values(args: argparse.Namespace) -> dict:
    """explore's parsed flags as the fields of its ExploreOptions: one per
    flag parsed, a_0 (--initial) checked, and left out when not given."""
    from pantarhei.bridge.reasoning import valid_scenes as validity
    from pantarhei.theory.option_table import option_table

    values = {o.name: getattr(args, o.name) for o in option_table() if hasattr(args, o.name)}
    if args.initial is not None:
        values["initial"] = validity.require_valid([t.strip() for t in args.initial.split(",") if t.strip()])
    else:
        del values["initial"]
    return values


def prolog(args: argparse.Namespace) -> int:
    from pantarhei.bridge.reasoning.written_theory import prolog_read
    from pantarhei.theory import prolog_modules
    from pantarhei.bridge.exploration.session import install

    eng = install()
    for name in prolog_modules():
        try:
            eng.use_module(name)
        except UserError as e:  # one module that does not load does not stop the others
            print(f"pantarhei prolog: {name} not loaded: {e}", file=sys.stderr)
    prolog_read(args.theory)     # the shipped theory, or the files given, as written
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
          "  ?- explore([oracle(synthetic), pours(40), out('/tmp/learned.pl')]).\n"
          "  ?- sample([pour_to_side], 3, 1, Rows), simulate(Rows, [oracle(synthetic)], Scores).\n"
          "  ?- validity:valid_antecedent([pour_to_side, pour_low]).\n"
          "End with halt. or Ctrl-D.", file=sys.stderr)
    eng.succeeds("prolog")
    return 0
