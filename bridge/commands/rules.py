"""`pantarhei rules`: a theory's rules, each with its body, head, the
likelihood that its expectation holds in such pours (the estimate pooled
from every pour learned from) and the pours it rests on, counted for the
expectation holding as `ask` counts them (theory/ask.pl's evidence/4)."""
from __future__ import annotations

import argparse
import json


def register(sub: argparse._SubParsersAction) -> None:
    from pantarhei.bridge.commands.querying import THEORY_HELP

    p = sub.add_parser("rules", help="a theory's rules with their likelihood and the pours behind them")
    p.add_argument("--theory", action="append", metavar="FILE", help=THEORY_HELP)
    p.add_argument("--expectation", metavar="E",
                   help="only the rules for E or neg(E) (see `pantarhei vocab`)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(run=rules)


def rule_rows(theory, expectation: str | None = None) -> list[dict]:
    """The theory's rules as rows: id, kind, body, head, expectation (the
    head's atom), learned, likelihood (that the expectation holds; None
    where the rule records no confidence), held and pours (the pours that
    could have been drawn for its body, and in how many the expectation
    held; None where it records none), in the vocabulary's order of
    expectations, then by body size and id."""
    from pantarhei.theory.lexicon import load_vocabulary

    order = {e: i for i, e in enumerate(load_vocabulary().expectation_names)}
    prov: dict[str, dict[str, object]] = {}
    for rid, key, value in theory.provenance:
        prov.setdefault(str(rid), {})[str(key)] = value
    rows = []
    for r in theory.rules:
        holds = not r.head.startswith("neg(")
        e = r.head if holds else r.head[4:-1]
        if expectation is not None and e != expectation:
            continue
        p = prov.get(r.id, {})
        c = p.get("confidence_permille")
        s, k = p.get("support"), p.get("kept")
        counted = isinstance(s, int) and isinstance(k, int)
        rows.append({"id": r.id, "kind": r.kind, "body": list(r.body), "head": r.head,
                     "expectation": e, "learned": r.id in theory.learned,
                     # as theory/learned_rules.pl's likelihood/3, the figure ask shows
                     "likelihood": (c if holds else 1000 - c) / 1000 if isinstance(c, int) else None,
                     "held": (k if holds else s - k) if counted else None,
                     "pours": s if counted else None,
                     "antecedent": p.get("antecedent")})
    rows.sort(key=lambda x: (order.get(x["expectation"], len(order)), x["expectation"],
                             len(x["body"]), x["id"]))
    return rows


def evidence_words(row: dict, glosses: dict[str, str]) -> str:
    """The pours behind a rule, in ask's words."""
    where = ", ".join(glosses.get(b, b) for b in row["body"])
    if row["pours"] is not None:
        if row["pours"] == 0:
            return "no such pour simulated: estimated from the pours nearby"
        of = "ordinary pours" if not row["body"] else f"pours of {where}"
        return f"held in {row['held']} of {row['pours']} {of}"
    if row["antecedent"] is not None:
        return f"the weighted pours of {row['antecedent']}"
    return "" if row["learned"] else "written by hand: no pours recorded"


def rules(args: argparse.Namespace) -> int:
    from pantarhei.bridge.commands.querying import utf8
    from pantarhei.bridge.errors import UserError
    from pantarhei.bridge.theories import loading
    from pantarhei.theory.lexicon import load_vocabulary

    vocab = load_vocabulary()
    e = args.expectation
    if e is not None:
        e = utf8(e, "--expectation").strip()
        if e not in vocab.expectation_names:
            import difflib

            near = difflib.get_close_matches(e, vocab.expectation_names, n=3, cutoff=0.5)
            hint = f" (did you mean {', '.join(near)}?)" if near else ""
            raise UserError(f"--expectation: unknown expectation '{e}'{hint}; see `pantarhei vocab`")
    theory = loading.load(args.theory)
    rows = rule_rows(theory, e)
    if args.json:
        print(json.dumps({"theory": theory.source, "rules": rows}, indent=1))
        return 0
    glosses = {n: p.gloss for n, p in vocab.propositions.items()}
    said = {x.name: x.gloss for x in vocab.expectations}
    print(f"theory: {theory.source} ({len(rows)} rule{'s' if len(rows) != 1 else ''})")
    arrows = {"strict": "->", "defeasible": "=>", "defeater": "~>"}
    current = None
    for row in rows:
        if row["expectation"] != current:
            current = row["expectation"]
            print(f"{current}" + (f": {said[current]}" if current in said else ""))
        body = ", ".join(row["body"]) or "(an ordinary pour)"
        share = (f"holds in {round(100 * row['likelihood'])}%" if row["likelihood"] is not None
                 else "no likelihood")
        ev = evidence_words(row, glosses)
        print(f"  {row['id']}: {body} {arrows.get(row['kind'], '=>')} {row['head']}")
        print(f"      {share}" + (f"; {ev}" if ev else ""))
    print("(holds in P%: the likelihood that the expectation holds in such pours, the rule's "
          "estimate pooled from every pour; held in K of N: the pours learned from that could "
          "have been drawn for its body, and in how many the expectation held)")
    return 0


def rule_antecedent(paths: list[str] | None, rule_id: str, seed: int) -> str:
    """`render --rule R`: the antecedent of rule R of the theory of `paths`
    (the shipped theory for none), comma-separated, said on stdout with
    the rule; UserError naming the nearest ids for a rule it lacks."""
    from pantarhei.bridge.errors import UserError
    from pantarhei.bridge.theories import loading

    theory = loading.load(paths)
    rule = next((r for r in theory.rules if r.id == rule_id), None)
    if rule is None:
        import difflib

        near = difflib.get_close_matches(rule_id, [r.id for r in theory.rules], n=3, cutoff=0.6)
        hint = f" (did you mean {', '.join(near)}?)" if near else ""
        raise UserError(f"--rule: {theory.source} has no rule {rule_id}{hint}; see `pantarhei rules`")
    print(f"rule {rule.id}: {', '.join(rule.body) or '(an ordinary pour)'} => {rule.head}: a pour "
          f"of its body sampled with seed {seed}, as the pours it rests on were drawn")
    return ",".join(rule.body)
