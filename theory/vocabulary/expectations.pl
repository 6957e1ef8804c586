% The 9 expectations watched in a pour.
%
% Read by SWI-Prolog and by clingo alike: ground facts only.
%
% The source moves in two stages, approach (start pose to pouring pose) and
% retreat (pouring pose to end pose); then everything settles.
%
% expectation(Name, Stage, Gloss): Stage is approach, retreat, settle, or
%   whole (over the whole pour). The oracle scores each in [0, 1]: 1 when
%   the expectation plainly holds, 0 when it plainly fails.

expectation(destination_still_approach, approach, "the destination stays still while the source moves into the pouring pose").
expectation(destination_still_retreat, retreat, "the destination stays still while the source moves away").
expectation(destination_still_settle, settle, "the destination stays still while everything settles").
expectation(destination_upright, whole, "the destination does not tip over").
expectation(source_clear, whole, "the source does not bump into the destination").
expectation(liquid_leaves_source, whole, "all the liquid leaves the source").
expectation(liquid_enters_destination, whole, "all the liquid enters the destination").
expectation(liquid_remains_in_destination, settle, "all the liquid remains in the destination").
expectation(no_spill, whole, "no liquid is spilled outside both bowls").
