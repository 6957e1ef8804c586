:- begin_tests(curiosity_foreign).

:- use_module(foreign).

% Stand-ins for foreign predicates, written in Prolog with known replies:
% the protocol of call_bridge/3 is the same whoever answers.
:- dynamic bridge:plt_echo/2, bridge:plt_fails/2, bridge:plt_error/2.
bridge:plt_echo(Request, _{got:Request}).
bridge:plt_fails(_, _) :- fail.
bridge:plt_error(_, _{error:'the store is locked'}).

test(reply) :-
    call_bridge(plt_echo, _{n:1}, R),
    get_dict(got, R, Got), get_dict(n, Got, 1).

test(not_registered, [throws(exploration_error("the oracle is not loaded: start Prolog with `pantarhei prolog`"))]) :-
    call_bridge(plt_missing, _{}, _).

test(fails, [throws(exploration_error("plt_fails failed"))]) :-
    call_bridge(plt_fails, _{}, _).

test(error_reply, [throws(exploration_error("the store is locked"))]) :-
    call_bridge(plt_error, _{}, _).

test(string_value) :-
    string_value(abc, S1), S1 == "abc",
    string_value("abc", S2), S2 == "abc".

:- end_tests(curiosity_foreign).
