"""Goals listed as a note ("goal: transfer all the water, nothing on the
bench, bowl stays put", "need: zero spill, full transfer"): each item said
as the outcome it wants, the list as "so that ... and so that ...", as
outcomes.hear reads goals; an item that names what is poured into the bowl
("get the full cup of broth into the bowl") is that pour, wanting it all in; one that empties a
source into it ("empty the bottle of oil into the bowl"), a pour from it, wanting it all out and in. A list with an item that says no outcome is
left as written, for the reader to read or refuse."""
from __future__ import annotations

import re

#: A list of goals after its label, up to the end of its sentence.
_LIST = re.compile(r"\b(?:my |our |the )?(?:goal|aim|objective|target|need|requirement)s?(?: is| are)?: *(?P<items>[^.?!;]+)")
#: Each item, said as the outcome it wants (the item's words as written -> the clause).
_ITEMS = tuple((re.compile(p), r) for p, r in (
    (r"^(?:transfer|move|get|pour|empty) (?:all|everything|every drop)(?: of)?(?: (?:the|my) [a-z]+)?(?: in| (?:in|into) (?:the )?[a-z]+)?$",
     "it all goes in"),
    (r"^(?:full|complete|total) transfer$", "it all goes in"),
    (r"^(?:nothing|none|no liquid|no water|not a drop|(?:zero|no|not one|not a single) drops?) (?:on|onto) (?:the |my )?[a-z]+$",
     "nothing spills"),
    (r"^(?:zero|no) (?:spill|spills|spillage|spilling|mess|splash|splashes|splashing|drips|dripping)"
     r"(?: (?:on|onto) (?:the |my )?[a-z]+)?$", "nothing spills"),
    (r"^(?:a )?(?:clean|neat|tidy) pour$", "nothing spills"),
    (r"^(?:the )?(?:bowl|destination) (?:stays|remains|staying|is) (?:put|still|in place|where it is)$", "the bowl stays put"),
    (r"^(?:the )?(?:bowl|destination) (?:does not|do not|will not|never|not) (?:move|moving|budge|budging|shift|shifting|slide|sliding)$",
     "the bowl stays put"),
    (r"^(?:the )?(?:bowl|destination) (?:stays|remains|staying|is) upright$", "the bowl stays upright"),
    (r"^(?:no|zero) (?:contact|bumps?|knocks?|collisions?)(?: between (?:the |my )?[a-z]+ & (?:the |my )?[a-z]+)?$",
     "the cup does not hit the bowl"),
    (r"^(?:the )?(?:source|cup|jug|bottle) (?:emptied|empty)$", "it all comes out"),
))
#: An item that names what is poured: "get the full cup of broth into the bowl" (poured so that it all goes in).
_POURED = re.compile(r"^(?:transfer|move|get|pour|empty) (?P<what>(?!all\b|everything\b|every\b)[a-z ]+?) (?:in|into) (?:the |my |a )?"
                     r"(?:[a-z]+ )?[a-z]+$")       # ("into a punch bowl")


def goal_list(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with a list of goals said as "so that ..." for
    each, and what is said back; `text` as it is otherwise."""
    m = _LIST.search(text)
    if m is None:
        return text, ()
    # ("no contact between the kettle and the bowl": one item)
    listed = re.sub(r"\bbetween ((?:the |my )?[a-z]+) and ((?:the |my )?[a-z]+)\b", r"between \1 & \2", m.group("items"))
    items = [i.strip() for i in re.split(r",|\band\b", listed) if i.strip()]
    said, poured = [], ""
    for item in items:
        clause = next((r for p, r in _ITEMS if p.match(item)), None)
        if clause is None and not poured and (what := _POURED.match(item)):
            # emptied: what is named is the source, all of it coming out ("empty the bottle of oil into the bowl")
            emptied = item.startswith("empty")
            clause = "it all comes out and it all goes in" if emptied else "it all goes in"
            poured = f"pour {'from ' * emptied}{what.group('what')} "
        if clause is None:
            return text, ()
        said.append(clause)
    wanted = " and ".join(f"so that {c}" for c in dict.fromkeys(said))
    return (f"{text[:m.start()]}{poured}{wanted}{text[m.end():]}",
            (f"{m.group(0).strip()}: read as {wanted}",))
