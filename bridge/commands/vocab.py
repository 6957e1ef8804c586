"""`pantarhei vocab`, `check`, `count`: the qualitative vocabulary."""
from __future__ import annotations

import argparse
import json

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.reasoning import valid_scenes as validity


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("vocab", help="list the parameters, propositions and expectations")
    form = p.add_mutually_exclusive_group()
    form.add_argument("--json", action="store_true", help="print JSON")
    form.add_argument("--markdown", action="store_true", help="print Markdown tables (as in docs/vocabulary.md)")
    p.set_defaults(run=vocab)

    p = sub.add_parser("check", help="is an antecedent (a set of propositions) valid?")
    p.add_argument("--engine", choices=validity.ENGINES, default="prolog")
    p.add_argument("props", nargs="+", metavar="PROP")
    p.set_defaults(run=check)

    p = sub.add_parser("count", help="count the valid antecedents")
    p.set_defaults(run=count)


def vocabulary_json() -> dict:
    v = load_vocabulary()
    return {
        "parameters": [{"name": p.name, "group": p.group, "unit": p.unit, "low": p.low,
                        "high": p.high, "prior": {"kind": "uniform", "low": p.prior_low, "high": p.prior_high},
                        "gloss": p.gloss} for p in v.parameters],
        "propositions": [{"name": p.name, "dimension": p.dimension, "rank": p.rank,
                          "aspect": v.dimensions[p.dimension].aspect,
                          "image_schema": v.dimensions[p.dimension].schema,
                          "role": v.dimensions[p.dimension].role, "gloss": p.gloss,
                          "model": _model_json(p.model)} for p in v.propositions.values()],
        "expectations": [{"name": e.name, "stage": e.stage, "gloss": e.gloss} for e in v.expectations],
        "constraints": [{"name": c, "gloss": g} for c, g in v.constraints.items()],
    }


def _model_json(m) -> dict:
    d = {"kind": m.kind, "parameter": m.param, "low": m.low, "high": m.high}
    if m.base:
        d["base"] = m.base
    return d


def model_words(m) -> str:
    unit = load_vocabulary().parameter(m.param).unit
    if m.kind == "uniform":
        return f"{m.param} ~ U[{m.low}, {m.high}] {unit}"
    return f"{m.param} = {m.base} + U[{m.low}, {m.high}] {unit}"


def vocab(args: argparse.Namespace) -> int:
    if args.json:
        print(json.dumps(vocabulary_json(), indent=1))
        return 0
    if args.markdown:
        print(markdown_tables(), end="")
        return 0
    v = load_vocabulary()
    print(f"{len(v.parameters)} parameters")
    for p in v.parameters:
        print(f"  {p.name:24} {p.unit:9} [{p.low}, {p.high}]  {p.gloss}")
    print(f"\n{len(v.propositions)} propositions in {len(v.dimensions)} dimensions")
    for d in v.dimensions.values():
        print(f"  {d.name} ({d.aspect}, {d.schema.upper()}, {d.role}): {d.gloss}")
        for name in d.values:
            p = v.propositions[name]
            print(f"    {p.rank}. {p.name:26} \"{p.gloss}\"  {model_words(p.model)}")
    print(f"\n{len(v.expectations)} expectations (each holds in a pour when its score is above "
          f"one half: of the liquid, a majority, not all of it)")
    for e in v.expectations:
        print(f"  {e.name:30} ({e.stage}) {e.gloss}")
    return 0


def check(args: argparse.Namespace) -> int:
    bad = validity.violations(args.props, args.engine)
    if not bad:
        print("valid")
        return 0
    print("invalid")
    for b in bad:
        print(f"  {b.words()}")
    return 1


def count(args: argparse.Namespace) -> int:
    print(validity.count_valid())
    return 0


def markdown_tables() -> str:
    """The vocabulary as the Markdown tables of docs/vocabulary.md (kept equal by a test)."""
    v = load_vocabulary()
    out = [f"#### The {len(v.parameters)} scene parameters", "",
           "| # | parameter | unit | bounds | prior | meaning |", "|---|---|---|---|---|---|"]
    for p in v.parameters:
        out.append(f"| {p.index + 1} | `{p.name}` | {p.unit} | [{p.low}, {p.high}] | U[{p.prior_low}, {p.prior_high}] | {p.gloss} |")
    out += ["", f"#### The {len(v.propositions)} scene propositions, in {len(v.dimensions)} dimensions", "",
            "| dimension | aspect | image schema | role | rank | proposition | gloss | generative model |",
            "|---|---|---|---|---|---|---|---|"]
    for d in v.dimensions.values():
        for name in d.values:
            p = v.propositions[name]
            first = p.rank == 1
            out.append(f"| {d.name if first else ''} | {d.aspect if first else ''} | "
                       f"{d.schema.upper() if first else ''} | {d.role if first else ''} | {p.rank} | "
                       f"`{p.name}` | {p.gloss} | {model_words(p.model)} |")
    out += ["", f"#### The {len(v.expectations)} expectations", "",
            "| expectation | stage | gloss |", "|---|---|---|"]
    for e in v.expectations:
        out.append(f"| `{e.name}` | {e.stage} | {e.gloss} |")
    return "\n".join(out) + "\n"
