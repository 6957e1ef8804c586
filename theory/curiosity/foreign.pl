:- module(curiosity_foreign,
          [ call_bridge/3,            % +Name, +Request, -Reply
            string_value/2            % +Value, -String
          ]).
/** <module> Calling the oracle: the foreign predicates of Algorithm 1

The numeric work of the exploration (sampling and simulating, the weights
of equation (1), the weighted plane fits, the novelty of candidates, the
outcome of an antecedent's simulations) is done in Python behind foreign
predicates of the module =bridge=, which `pantarhei explore` and
`pantarhei prolog` register:

  - bridge:exploration_begin(+Settings, -Begun)
  - bridge:exploration_simulate(+Request, -Reply)
  - bridge:exploration_steepest_plane(+Request, -Reply)
  - bridge:exploration_significant_planes(+Request, -Reply)
  - bridge:exploration_probe(+Request, -Reply)
  - bridge:exploration_predict(+Request, -Reply)
  - bridge:exploration_teach(+Request, -Reply)
  - bridge:exploration_qualify(+Request, -Reply)
  - bridge:exploration_checkpoint(+Request, -Reply)
  - bridge:exploration_general(+Request, -Reply)
  - bridge:exploration_end(+Request, -Reply)
  - bridge:oracle_sample(+Request, -Reply), bridge:oracle_simulate(+Request, -Reply),
    bridge:oracle_describe(+Request, -Reply): sample/4, simulate/3 and
    describe/2 of oracle_prompt.pl, the oracle at the Prolog prompt

Python holds no setting of the run: each request carries those its
handler needs (the batch, the seed, the ridge, ...), from the settings of
explore/1 (settings.pl), the only ones. Requests and replies are dicts of
atoms, strings, numbers, lists and dicts (strings come back as atoms, and the booleans as =true= and
=false=); a reply =|_{error: Text}|= raises =|exploration_error(Text)|=,
which prints as its Text.
*/

:- multifile prolog:message//1.

prolog:message(exploration_error(Text)) -->
    [ '~w'-[Text] ].

%!  call_bridge(+Name:atom, +Request:dict, -Reply:dict) is det.
%
%   Call the foreign predicate bridge:Name/2 with Request, and take its
%   reply.
%
%   @error exploration_error(Text) when the foreign predicate is not
%   registered, fails, or replies with an error.
call_bridge(Name, Request, Reply) :-
    (   current_predicate(bridge:Name/2)
    ->  true
    ;   throw(exploration_error("the oracle is not loaded: start Prolog with `pantarhei prolog`"))
    ),
    Goal =.. [Name, Request, Reply0],
    (   call(bridge:Goal)
    ->  true
    ;   format(string(M), "~w failed", [Name]),
        throw(exploration_error(M))
    ),
    (   get_dict(error, Reply0, Message)
    ->  string_value(Message, M),
        throw(exploration_error(M))
    ;   Reply = Reply0
    ).

%!  string_value(+Value, -String:string) is det.
%
%   String is Value (a string, or an atom as replies hold them) as a string.
string_value(V, S) :- ( string(V) -> S = V ; atom_string(V, S) ).
