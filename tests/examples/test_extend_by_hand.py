"""examples/extend_by_hand/ on the shipped learned theory: a rule written by
hand whose body strictly contains the body of a learned rule with the
complementary head overrides it without a sup/2 line (specificity, as
learned rules override each other; docs/theory-formats.md). The tests
read the shipped theory's rules as they are, never its numbers."""
from __future__ import annotations

import json
import re
from pathlib import Path

from pantarhei.bridge.theories import loading
from pantarhei.theory import default_theory

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "extend_by_hand"


def test_the_example_rule_wins_on_the_shipped_theory_without_sup(cli) -> None:
    hand = EXAMPLE / "shipped.dfl"
    assert ">" not in hand.read_text().replace("=>", "")        # no superiority written
    shipped = str(default_theory())
    args = ("ask", "--props", "pour_very_high,pour_centred", "--theory", shipped, "--theory", str(hand))
    out = json.loads(cli(*args, "--json").out)["outcomes"]["no_spill"]
    assert out["verdict"] == "fails" and out["rule"] == "k1"
    # every learned rule for no_spill that applies is overridden: by k1,
    # or by a learned rule that concludes as k1 does
    theory = loading.load([shipped])
    applying = [r.id for r in theory.rules if r.head == "no_spill"
                and set(r.body) <= {"pour_very_high", "pour_centred"}]
    assert applying and all(r in theory.learned for r in applying)
    agreeing = {r.id for r in theory.rules if r.head == "neg(no_spill)"} | {"k1"}
    why = cli(*args, "--why", "-no_spill")
    assert why.code == 0, why.err
    for r in applying:
        by = re.search(rf"the opposing rule {r} is overridden by (\w+)", why.out)
        assert by and by.group(1) in agreeing, why.out


def test_a_hand_rule_more_specific_than_the_deciding_learned_rule_wins(cli, tmp_path: Path) -> None:
    # per expectation, the rule that decides a scene of the shipped theory,
    # and a rule by hand for the complement whose body is the whole scene
    shipped = str(default_theory())
    scene = ["light_liquid", "pour_centred", "pour_very_high"]
    before = json.loads(cli("ask", "--props", ",".join(scene), "--theory", shipped,
                            "--json").out)["outcomes"]
    theory = loading.load([shipped])
    rules = {r.id: r for r in theory.rules}
    lines, expected = [], {}
    for e, o in before.items():
        decided = rules.get(o["rule"])
        if decided is None or set(decided.body) == set(scene):
            continue                    # undecided, or a learned rule as specific
        assert decided.id in theory.learned
        head = decided.head[4:-1] if decided.head.startswith("neg(") else f"-{decided.head}"
        lines.append(f"k_{e}: {', '.join(scene)} => {head}")
        expected[e] = f"k_{e}"
    assert expected, "the shipped theory decides nothing in the scene"
    hand = tmp_path / "hand.dfl"
    hand.write_text("\n".join(lines) + "\n")
    after = json.loads(cli("ask", "--props", ",".join(scene), "--theory", shipped,
                           "--theory", str(hand), "--json").out)["outcomes"]
    for e, k in expected.items():
        assert after[e]["rule"] == k, (e, after[e])
        flipped = {"holds": "fails", "fails": "holds", "uncertain": None}[before[e]["verdict"]]
        assert flipped is None or after[e]["verdict"] == flipped
