% A small theory of pouring in the format the exploration writes: rules
% learned from simulations (learned/1), with their provenance. Among
% learned rules the more specific one wins (r4 beats r3: its body
% contains r3's).
setting(source, "hand-made example of a learned theory").

rule(r1, defeasible, neg(no_spill)).
body(r1, pour_to_side).
learned(r1).
provenance(r1, simulations, 40).

rule(r2, defeasible, no_spill).
body(r2, pour_centred).
learned(r2).

rule(r3, defeasible, liquid_leaves_source).
body(r3, pour_steeply_tilted).
learned(r3).

rule(r4, defeasible, neg(liquid_leaves_source)).
body(r4, pour_steeply_tilted).
body(r4, light_liquid).
learned(r4).

rule(r5, defeasible, liquid_leaves_source).
body(r5, pour_upside_down).
learned(r5).

rule(r6, defeasible, liquid_enters_destination).
body(r6, pour_centred).
body(r6, pour_steeply_tilted).
learned(r6).

rule(r7, defeasible, neg(liquid_remains_in_destination)).
body(r7, light_liquid).
body(r7, end_upright).
body(r7, end_low).
learned(r7).

rule(r8, defeasible, liquid_remains_in_destination).
body(r8, pour_centred).
learned(r8).

rule(r9, defeasible, destination_upright).
learned(r9).

rule(r10, defeasible, neg(destination_upright)).
body(r10, light_destination).
body(r10, fast_approach).
learned(r10).

rule(r11, defeasible, neg(source_clear)).
body(r11, pour_low).
body(r11, pour_near_rim).
learned(r11).

rule(r12, defeasible, source_clear).
body(r12, pour_high).
learned(r12).
