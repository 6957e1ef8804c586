% The 9 expectations watched in a pour.
%
% Read by SWI-Prolog and by clingo alike: ground facts only.
%
% The source moves in two stages, approach (start pose to pouring pose) and
% retreat (pouring pose to end pose); then everything settles.
%
% expectation(Name, Stage, Gloss): Stage is approach, retreat, settle, or
%   whole (over the whole pour). The oracle scores each in [0, 1]: 1 when
%   the expectation plainly holds, 0 when it plainly fails; it holds in a
%   pour when its score is above one half (of the liquid: a majority, not
%   all of it), and the gloss says so.

expectation(destination_still_approach, approach, "the destination stays still while the source moves into the pouring pose").
expectation(destination_still_retreat, retreat, "the destination stays still while the source moves away").
expectation(destination_still_settle, settle, "the destination stays still while everything settles").
expectation(destination_upright, whole, "the destination does not tip over").
expectation(source_clear, whole, "the source does not bump into the destination").
expectation(liquid_leaves_source, whole, "most of the liquid leaves the source (more than half)").
expectation(liquid_enters_destination, whole, "most of the liquid enters the destination (more than half)").
expectation(liquid_remains_in_destination, settle, "most of what enters the destination stays in it (also when none enters)").
expectation(no_spill, whole, "less than half of the liquid is spilled outside both bowls").
