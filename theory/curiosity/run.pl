:- module(curiosity_run,
          [ explore/1,                % +Options
            explore_result/2          % +Options, -Result
          ]).
/** <module> Running an exploration: explore/1

The entry of Algorithm 1: read the options (settings.pl), begin the
exploration on the oracle's side, run the loop (loop.pl) from a_0 or the
saved state (state.pl), qualify the explored antecedents, learn the
general rules of every pour (unless general(false)) and write the learned
theory with both layers, once (writer.pl), and end. The second layer is
the curiosity's (second_layer of interface.pl): the learning curiosity
writes one layer, the rules of its explored antecedents. An error ends
the exploration on the oracle's side too (aborted), then propagates.
*/

:- use_module(library(lists)).
:- use_module(foreign).
:- use_module(settings).
:- use_module(state).
:- use_module(loop).
:- use_module(writer).
:- use_module(interface).

%!  explore(+Options:list) is det.
%
%   Run Algorithm 1 and write the learned theory. Options: those of the
%   option table of theory/defaults.pl (docs/options.md), each as
%   Name(Value), e.g. explore([oracle(synthetic), pours(40), out(File)]):
%   their types, ranges and defaults are there, and used_by/2 there says
%   which curiosity reads which (another is refused: the learning
%   curiosity's budget is pours(N), the others' budget(N)). Besides them:
%
%     - oracle_options(+Dict): arguments of the oracle (a dict)
%
%   @error exploration_error(Text) for bad options or a failing oracle.
explore(Options) :-
    settings(Options, Settings),
    course_options(Settings, Course),
    by_curiosity(Settings, progress_bar(Settings, Bar)),
    call_bridge(exploration_begin, Settings.put(_{course:Course, bar:Bar}), Begun),
    catch(explore_loop(Settings, Begun), E,
          ( catch(call_bridge(exploration_end, _{aborted:true}, _), _, true),
            throw(E) )).

%   explore_loop(+Settings, +Begun): the loop from its initial state, then
%   the learned theory written and the exploration ended.
explore_loop(Settings, Begun) :-
    initial_state(Begun, Settings, S0),
    loop(S0, Settings, S, Stop),
    S = st(_, Explored, ANew, SetAside),
    length(ANew, Left),
    by_curiosity(Settings, theory_layout(Layout)),
    learned(Explored, SetAside, Settings, Layout, Stop, Left, Facts),
    by_curiosity(Settings, second_layer(Explored, Facts, Settings, General)),
    write_theory(Settings.out, Settings, Layout, Facts, General),
    length(Explored, N),
    by_curiosity(Settings, progress_bar(Settings, Budget)),
    call_bridge(exploration_end, _{out:Settings.out, stopped:Stop, explored:N,
                                   a_new:Left, oracle:Settings.oracle, seed:Settings.seed,
                                   budget:Budget}, _).

%!  explore_result(+Options:list, -Result) is det.
%
%   Like explore/1, but never throws: Result is ok, or error(Text) with one
%   line saying what went wrong. For hosts that want a value, not an
%   exception.
explore_result(Options, Result) :-
    catch(( explore(Options), Result = ok ), E, error_result(E, Result)).

%   error_result(+Error, -Result): error(Text), Text the first line of
%   Error's message.
error_result(exploration_error(Text), error(Text)) :- !.
error_result(E, error(Text)) :-
    (   catch(message_lines(E, Lines), _, fail)
    ->  with_output_to(string(Text0), print_message_lines(current_output, '', Lines)),
        split_string(Text0, "\n", " ", [Text|_])
    ;   format(string(Text), "~q", [E])
    ).

message_lines(E, Lines) :-
    '$messages':translate_message(E, Lines, []).
