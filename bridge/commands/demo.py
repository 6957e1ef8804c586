"""`pantarhei demo`: the main job on the embedded defaults."""
from __future__ import annotations

import argparse

from pantarhei.oracle.vocabulary import load_vocabulary

from .. import validity


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("demo", help="run the main job on the embedded defaults")
    p.set_defaults(run=demo)


#: A few antecedents, and what the constraints say of them.
EXAMPLES = (
    ("an ordinary pour", ["pour_near_rim", "pour_low", "pour_half_tilted", "slow_approach"]),
    ("pouring from the side, steeply", ["pour_to_side", "pour_steeply_tilted"]),
    ("centred below the rim", ["pour_centred", "pour_below_rim"]),
    ("high, then lowered before pouring", ["start_high", "approach_lowering"]),
)


def demo(args: argparse.Namespace) -> int:
    v = load_vocabulary()
    print(f"The vocabulary of pouring: {len(v.parameters)} parameters, "
          f"{len(v.propositions)} propositions in {len(v.dimensions)} dimensions, "
          f"{len(v.expectations)} expectations.")
    print(f"Valid antecedents: {validity.count_valid():,}\n")
    for words, props in EXAMPLES:
        by_prolog = validity.violations(props, "prolog")
        by_asp = validity.violations(props, "asp")
        verdict = "valid" if not by_prolog else "invalid"
        agree = "Prolog and clingo agree" if by_prolog == by_asp else "Prolog and clingo DISAGREE"
        print(f"{words}: {', '.join(props)}\n  {verdict} ({agree})")
        for b in by_prolog:
            print(f"  - {b.words()}")
    return 0
