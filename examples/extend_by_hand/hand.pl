% The rule of hand.dfl in the native format: the same theory.
rule(h1, defeasible, liquid_leaves_source).
body(h1, light_liquid).
body(h1, pour_steeply_tilted).
body(h1, slow_retreat).
sup(h1, r4).
