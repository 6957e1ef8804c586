"""The reader's phrase patterns are compiled only when a text holds one of
their cues (bridge/reasoning/cued.py): a cue must be in every text the
pattern matches, or a phrase would go unread."""
from __future__ import annotations

import re
from pathlib import Path

from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.words import PHRASES, rewrites

CORPUS = Path(__file__).with_name("question_kinds.tsv")


def _texts() -> list[str]:
    lines = CORPUS.read_text(encoding="utf-8").splitlines()
    return [line.split("\t")[0].lower() for line in lines if line and not line.startswith("#")]


def _inflected() -> list[str]:
    """Each phrase of words.py said with its words inflected ("moving in",
    "tilted halfway"), its optional parts left out."""
    out = []
    for entry in PHRASES:
        for phrase in entry[1]:
            if phrase.startswith("re:") or phrase.startswith("re("):
                continue
            words = [w for w in re.sub(r"\[[^\]]*\]", " ", phrase).split()]
            for ending in ("ing", "ed", "s"):
                out.append(" ".join((w[:-1] if w.endswith("e") else w) + ending for w in words))
    return out


def test_a_cued_pattern_finds_what_its_compiled_pattern_finds():
    patterns = [p for p, _, _ in rewrites() if isinstance(p, Cued)]
    assert patterns and any(p.cues for p in patterns)
    texts = _texts() + _inflected()
    assert len(texts) > 300
    for p in patterns:
        plain = re.compile(p.source)
        for text in texts:
            assert bool(p.search(text)) == bool(plain.search(text)), (p.source[:60], text)


def test_a_text_without_a_cue_compiles_nothing():
    p = Cued(r"\bspill(?:s|ed)?\b", ["spill"])
    assert p.search("does it splash") is None and "pattern" not in vars(p)
    assert p.search("will it spill over").group() == "spill" and "pattern" in vars(p)
    assert Cued(r"\bx\b", None).search("a x b")


def test_a_regular_expression_is_cued_by_the_literals_it_names():
    p = Cued.of([r"re(thick|stick):\b(?:thicker|stickier) than water\b", "move in"])
    assert p.cues == ("thick", "stick", "mov")
    assert p.search("a liquid thinner than water") is None and "pattern" not in vars(p)
    assert p.search("something stickier than water").group() == "stickier than water"
