:- module(curiosity,
          [ explore/1,                % +Options
            explore_result/2,         % +Options, -Result
            sample/4,                 % +Props, +N, +Seed, -Rows
            simulate/3,               % +Rows, +Options, -Scores
            default_initial/1,        % -Props
            describe/2,               % +Row, -Props
            direction/3,              % +Gradient, +MeanScore, -Direction
            modify/5,                 % +Props, +Direction, +Breadth, +Exclude, -New
            modify_past/4,            % +Props, +Moves, +Exclude, -New
            parameter_mean/3,         % +Props, +Param, -Mean
            rule_facts/3,             % +Learned, +Qualified, -Facts
            write_theory/3            % +File, +Settings, +Facts
          ]).
/** <module> Curiosity-driven exploration: Algorithm 1 of the paper

The control flow of Algorithm 1 lives here: the queue A_new, the explored
antecedents, choosing the steepest plane, modify, the stopping rule,
qualify, and writing the learned rules. The numeric work (sampling and
simulating, the weights of equation (1), the weighted plane fits, the
outcome of an antecedent's simulations) is done in Python behind foreign
predicates of the module =bridge=, which `pantarhei explore` and
`pantarhei prolog` register:

  - bridge:exploration_begin(+Settings, -Begun)
  - bridge:exploration_simulate(+Request, -Reply)
  - bridge:exploration_best_plane(+Request, -Reply)
  - bridge:exploration_predict(+Request, -Reply)
  - bridge:exploration_qualify(+Request, -Reply)
  - bridge:exploration_checkpoint(+Request, -Reply)
  - bridge:exploration_end(+Request, -Reply)
  - bridge:oracle_sample(+Request, -Reply), bridge:oracle_simulate(+Request, -Reply),
    bridge:oracle_describe(+Request, -Reply): sample/4, simulate/3 and
    describe/2, the oracle at the Prolog prompt

Requests and replies are JSON text; a reply =|{"error": Text}|= raises
=|exploration_error(Text)|=.

The loop's state is the term st(Iteration, Explored, ANew, SetAside): Explored lists
ant(Id, Props, Parent, Via) in the order of exploration, ANew lists
cand(Props, Parent, Via) in the order they are popped (for the paper's
curiosity a queue, the oldest first; for the discovering one the most novel
first). Via is `initial`; `prior` for the empty antecedent explored
last (prior/1); via(Expectation, Param, Sign) for the plane,
parameter and sign (up or down) that produced it; `near` for a neighbour of
the antecedent explored before it; `jump` for a random valid antecedent; or
more(Id, K) for the K-th more batch of an explored antecedent. SetAside
lists aside(Iteration, Attempt, Props) for each candidate set aside after
its probe (below). The state is
saved after every explored antecedent, so an exploration can resume.

Two curiosities share the loop (option curiosity/1):

  - `paper`: Algorithm 1 as the paper states it. The steepest plane of all
    explored antecedents is followed when its slope exceeds the threshold,
    and modify/5 moves the parameters of its largest gradient components by
    one rank.
  - `discover`: a plane's slopes count only where they beat shuffles of the
    same weighted pours (a permutation test at the significance level given
    as threshold). The candidates of a step are the antecedents that move
    the pours past the point where a significant plane's verdict flips
    (modify_past/4, every significant plane and parameter), the neighbours
    of the antecedent just explored (neighbours/3), and `jumps` uniformly
    random valid antecedents (far from anything explored; as many as a
    batch has pours by default).
    Each candidate and each of A_new gets its novelty, the chance that it
    shows a behaviour not yet got as a forest of every pour so far predicts
    it (bridge/exploration/novelty.py); A_new keeps the most novel of those
    that reach the novelty level once scaled by the probes' mean score so
    far (below), so it dries up as the probes stop finding anything
    new. When nothing reaches it, the antecedent
    just explored gets more pours (resample/1), which may change the forest's
    mind; when that is spent too and A_new is empty, the exploration stops.
    The forest's guess is checked before a batch is spent on it: the first
    `probe` pours of the candidate's batch are simulated, and when they do
    not show a new, reproducible consequent the candidate is set aside and
    the next one probed (choose/6). The budget is then in pours: max_rules
    batches' worth, batches and probes together.
    With prior(1) (the default) the last batch of the budget (or the
    next, when A_new is empty) goes to the priors: the empty antecedent,
    every parameter drawn from its prior, unprobed and unranked. A question
    leaves parameters unsaid, and they follow their priors; the antecedents
    curiosity explores set nearly every parameter away from them, so
    without this batch the general rules learned from the pours
    (bridge/learning/) answer every question by extrapolation. Coming last,
    it leaves the curiosity's course before it as it is without the priors
    (the budget less one batch).
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module(library(http/json)).
:- use_module(theory_files).
:- use_module(vocabulary).
:- use_module(validity).
:- use_module(default_values).


%!  explore(+Options:list) is det.
%
%   Run Algorithm 1 and write the learned theory. Options (the defaults
%   of those marked * are in theory/defaults.pl):
%
%     - oracle(+Name)*: pybullet or synthetic
%     - max_rules(+N)*: stop after N explored antecedents (discover: the
%       pours of N batches, its batches and probes)
%     - samples(+N): simulations per explored antecedent (default: the
%       number of parameters plus one)
%     - curiosity(+Mode)*: discover or paper (see the module's documentation)
%     - queue(+N)*: A_new keeps the N most novel candidates (discover)
%     - jumps(+N)*: uniformly random valid antecedents drawn as candidates
%       each step (discover)
%     - threshold(+X)*: for discover, the significance level of the
%       permutation test (default significance_permille); for paper, the
%       slope below which nothing new is explored (default threshold_permille)
%     - permutations(+N)*: shuffles of the permutation test (discover)
%     - resample(+N)*: more batches of an antecedent whose planes are all
%       undecided and that queued nothing new (discover); max_rules then
%       counts batches
%     - novelty(+X)*: the estimated chance of a new behaviour, from 0 to 1,
%       a candidate needs to be queued, scaled by the probes' mean score
%       so far (discover; default novelty_permille)
%     - probe(+N)*: pours of a candidate's probe, 0 for none (discover)
%     - probe_attempts(+N)*: candidates probed at most in a step (discover)
%     - cover(+N)*: the last probe of a step goes to the candidate whose
%       rarest proposition the fewest pours so far hold, when fewer than N
%       do; 0 for never (discover)
%     - prior(+B)*: 1 to explore the priors (the empty antecedent, every
%       parameter from its prior, as a question's unsaid ones) with the
%       last batch of the budget, 0 not to (discover)
%     - seed(+S)*: seed of every random choice
%     - initial(+Props)*: a_0 (default_initial/1)
%     - breadth(+K)*: the paper's modify uses the K largest gradient components
%     - ridge(+X)*: L2 penalty of the plane fits (0 is plain least squares)
%     - qualify(+Mode)*: weighted or argmax (the paper's rule)
%     - out(+File)*: the learned theory (relative to theory/)
%     - store(+File): the SQLite store of simulations and state
%     - resume(+Bool): continue the saved exploration with these settings
%     - executor(+E), workers(+N), ray_address(+A): where to simulate
%     - oracle_options(+Dict): arguments of the oracle (a dict or JSON text)
%     - progress(+Bool): show a progress bar (default true)
%
%   @error exploration_error(Text) for bad options or a failing oracle.
explore(Options) :-
    settings(Options, Settings),
    call_bridge(exploration_begin, Settings, Begun),
    catch(explore_loop(Settings, Begun), E,
          ( catch(call_bridge(exploration_end, _{aborted:true}, _), _, true),
            throw(E) )).

explore_loop(Settings, Begun) :-
    initial_state(Begun, Settings, S0),
    loop(S0, Settings, S, Stop),
    S = st(_, Explored, ANew, SetAside),
    length(ANew, Left),
    learned(Explored, SetAside, Settings, Stop, Left, Facts),
    write_theory(Settings.out, Settings, Facts),
    length(Explored, N),
    call_bridge(exploration_end, _{out:Settings.out, stopped:Stop, explored:N,
                                   a_new:Left}, _).

%!  explore_result(+Options:list, -Result) is det.
%
%   Like explore/1, but never throws: Result is ok, or error(Text) with one
%   line saying what went wrong. For hosts that want a value, not an
%   exception.
explore_result(Options, Result) :-
    catch(( explore(Options), Result = ok ), E, error_result(E, Result)).

error_result(exploration_error(Text), error(Text)) :- !.
error_result(E, error(Text)) :-
    (   catch(message_lines(E, Lines), _, fail)
    ->  with_output_to(string(Text0), print_message_lines(current_output, '', Lines)),
        split_string(Text0, "\n", " ", [Text|_])
    ;   format(string(Text), "~q", [E])
    ).

message_lines(E, Lines) :-
    '$messages':translate_message(E, Lines, []).

% ----------------------------------------------------------------------
% Settings

settings(Options, S) :-
    must_be(list, Options),
    aggregate_all(count, parameter(_, _, _, _, _), NParams),
    DefaultSamples is NParams + 1,
    default_initial(DefaultInitial),
    default(threshold, DSlope),
    default(significance, DLevel),
    option_default(curiosity, Options, Curiosity),
    (   memberchk(Curiosity, [paper, discover])
    ->  true
    ;   throw(exploration_error("curiosity: expected paper or discover"))
    ),
    (   Curiosity == paper -> DThreshold = DSlope ; DThreshold = DLevel ),
    option_default(permutations, Options, Permutations),
    check_positive(permutations, Permutations),
    option_default(resample, Options, Resample),
    (   integer(Resample), Resample >= 0 -> true
    ;   throw(exploration_error("resample: expected a whole number >= 0"))
    ),
    option_default(queue, Options, Queue),
    check_positive(queue, Queue),
    option_default(jumps, Options, Jumps),
    check_positive(jumps, Jumps),
    option_default(probe, Options, Probe),
    (   integer(Probe), Probe >= 0 -> true
    ;   throw(exploration_error("probe: expected a whole number >= 0"))
    ),
    option_default(probe_attempts, Options, Attempts),
    check_positive(probe_attempts, Attempts),
    option_default(cover, Options, Cover),
    (   integer(Cover), Cover >= 0 -> true
    ;   throw(exploration_error("cover: expected a whole number >= 0"))
    ),
    option_default(prior, Options, Prior),
    (   memberchk(Prior, [0, 1]) -> true
    ;   throw(exploration_error("prior: expected 0 or 1"))
    ),
    option_default(novelty, Options, Novelty0),
    (   number(Novelty0), Novelty0 >= 0, Novelty0 =< 1 -> Novelty is float(Novelty0)
    ;   throw(exploration_error("novelty: expected a number from 0 to 1"))
    ),
    option_default(oracle, Options, Oracle),
    option_default(max_rules, Options, Max),
    option(samples(Samples), Options, DefaultSamples),
    option(threshold(Threshold0), Options, DThreshold),
    option_default(seed, Options, Seed),
    option(initial(Initial0), Options, DefaultInitial),
    option_default(breadth, Options, Breadth),
    option_default(ridge, Options, Ridge0),
    option_default(qualify, Options, Qualify),
    option(resume(Resume), Options, false),
    option(executor(Executor), Options, local),
    option(progress(Progress), Options, true),
    default_out(DefaultOut),
    option(out(Out0), Options, DefaultOut),
    check_positive(max_rules, Max),
    check_positive(samples, Samples),
    check_positive(breadth, Breadth),
    (   integer(Seed) -> true ; throw(exploration_error("seed: expected an integer")) ),
    (   number(Threshold0), Threshold0 >= 0
    ->  Threshold is float(Threshold0)
    ;   throw(exploration_error("threshold: expected a number >= 0"))
    ),
    (   Curiosity == discover, Threshold > 1
    ->  throw(exploration_error("threshold: a significance level is at most 1"))
    ;   true
    ),
    (   memberchk(Qualify, [weighted, argmax])
    ->  true
    ;   throw(exploration_error("qualify: expected weighted or argmax"))
    ),
    (   number(Ridge0), Ridge0 >= 0
    ->  Ridge is float(Ridge0)
    ;   throw(exploration_error("ridge: expected a number >= 0"))
    ),
    check_initial(Initial0, Initial),
    absolute_file_name(Out0, Out),
    S0 = _{oracle:Oracle, max_rules:Max, samples:Samples, threshold:Threshold,
           seed:Seed, initial:Initial, breadth:Breadth, ridge:Ridge, qualify:Qualify,
           resume:Resume, executor:Executor, progress:Progress, out:Out,
           curiosity:Curiosity, permutations:Permutations, resample:Resample,
           novelty:Novelty, queue:Queue, jumps:Jumps, probe:Probe,
           probe_attempts:Attempts, cover:Cover, prior:Prior},
    optional(store, Options, S0, S1),
    optional(workers, Options, S1, S2),
    optional(ray_address, Options, S2, S3),
    (   option(oracle_options(OO), Options)
    ->  (   is_dict(OO) -> OracleOptions = OO ; atom_json_dict(OO, OracleOptions, []) ),
        put_dict(oracle_options, S3, OracleOptions, S)
    ;   S = S3
    ).

%   option_default(+Key, +Options, -Value): the option Key(Value) of
%   Options, or the default of theory/defaults.pl.
option_default(Key, Options, Value) :-
    default(Key, Default),
    Option =.. [Key, Value],
    option(Option, Options, Default).

optional(Key, Options, S0, S) :-
    Opt =.. [Key, V],
    (   option(Opt, Options)
    ->  (   Key == store
        ->  absolute_file_name(V, Value)
        ;   Value = V
        ),
        put_dict(Key, S0, Value, S)
    ;   S = S0
    ).

default_out(File) :-
    module_property(curiosity, file(Here)),
    file_directory_name(Here, Dir),
    default(theory, Relative),
    directory_file_path(Dir, Relative, File).

check_positive(_, N) :- integer(N), N > 0, !.
check_positive(Name, _) :-
    format(string(M), "~w: expected a whole number above 0", [Name]),
    throw(exploration_error(M)).

check_initial(Props, Set) :-
    (   is_list(Props) -> true
    ;   throw(exploration_error("initial: expected a list of propositions"))
    ),
    sort(Props, Set),
    violations(Set, Why),
    (   Why = [] -> true
    ;   Why = [unknown(_, W)|_]
    ->  format(string(M), "initial antecedent: ~s", [W]),
        throw(exploration_error(M))
    ;   Why = [violation(_, _, _, W)|_],
        format(string(M), "initial antecedent is invalid: ~s", [W]),
        throw(exploration_error(M))
    ).

initial_state(Begun, Settings, S) :-
    (   get_dict(state, Begun, Text), Text \== '', Text \== ""
    ->  term_string(S, Text)
    ;   S = st(0, [], [cand(Settings.initial, none, initial)], [])
    ).

% ----------------------------------------------------------------------
% The loop

%!  loop(+S0, +Settings, -S, -Stop) is det.
%
%   Explore antecedents from A_new until it is empty (Stop = a_new_empty)
%   or the budget of max_rules batches of simulations would be exceeded by
%   another step (Stop = max_rules): as many antecedents for the paper's
%   curiosity, which samples each once; the discovering one may sample an
%   undecided antecedent again and spends pours on probes, and so explores
%   at most as many with the same budget of pours. With prior(1) the
%   priors take the batch before the step that could exceed the budget
%   with it, or the next when A_new is empty (priors_pending/2).
loop(S0, Settings, S, Stop) :-
    next_move(S0, Settings, Move),
    (   Move = stop(Stop)
    ->  S = S0
    ;   Move == priors
    ->  S0 = st(I, Explored, ANew, SetAside),
        step(st(I, Explored, [cand([], none, prior)|ANew], SetAside), Settings, S1),
        loop(S1, Settings, S, Stop)
    ;   step(S0, Settings, S1),
        loop(S1, Settings, S, Stop)
    ).

%   next_move(+State, +Settings, -Move): what the loop does next: `priors`
%   (their batch), `step` (the next of A_new) or stop(Why).
next_move(S0, Settings, Move) :-
    S0 = st(_, Explored, ANew, _),
    spent(S0, Settings, Spent),
    step_cost(Settings, Most),
    Budget is Settings.max_rules * Settings.samples,
    (   priors_pending(Explored, Settings),
        Spent + Settings.samples =< Budget,
        ( ANew == [] ; Spent + Most + Settings.samples > Budget )
    ->  Move = priors
    ;   ANew == []
    ->  Move = stop(a_new_empty)
    ;   Spent + Most > Budget
    ->  Move = stop(max_rules)
    ;   Move = step
    ).

%   priors_pending(+Explored, +Settings): the priors are to be explored
%   (prior(1)) and have not been yet. Their batch is the last of the
%   budget, or comes when A_new is empty: their pours then teach the
%   general rules without changing the course of the curiosity before
%   them.
priors_pending(Explored, Settings) :-
    Settings.curiosity == discover,
    Settings.prior =:= 1,
    \+ memberchk(ant(_, [], _, prior), Explored).

%   spent(+State, +Settings, -Pours): the pours spent so far: a batch per
%   iteration and a probe per candidate set aside after its probe.
spent(st(I, _, _, SetAside), Settings, Pours) :-
    length(SetAside, K),
    probe_size(Settings, M),
    Pours is I * Settings.samples + K * M.

%   step_cost(+Settings, -Pours): the most pours a step spends: its batch,
%   and the probes of the candidates it may set aside. The loop stops when
%   that would exceed the budget, so a step never depends on the budget
%   and a longer run continues a shorter one.
step_cost(Settings, Pours) :-
    probe_size(Settings, M),
    Pours is Settings.samples + (Settings.probe_attempts - 1) * M.

probe_size(Settings, M) :-
    (   Settings.curiosity == discover
    ->  M is min(Settings.probe, Settings.samples)
    ;   M = 0
    ).

%   One iteration of Algorithm 1: pop a_c (for the discovering curiosity
%   with probes: the first candidate whose probe passes, choose/6), explore
%   it, fit the planes of every explored antecedent, and modify the one with
%   the steepest plane (for the discovering curiosity: the steepest
%   significant plane).
step(S0, Settings, st(I1, Explored1, ANew, SetAside)) :-
    S0 = st(I, Explored, _, SetAside0),
    I1 is I + 1,
    choose(S0, Settings, cand(Props, Parent, Via), Attempt, Rest, Probes),
    findall(aside(I1, K, P), member(probe(P, _, false, K, _), Probes), NewAside),
    append(SetAside0, NewAside, SetAside),
    (   Via = more(Id, _)
    ->  Explored1 = Explored
    ;   length(Explored, N0),
        N is N0 + 1,
        format(atom(Id), "a~w", [N]),
        append(Explored, [ant(Id, Props, Parent, Via)], Explored1)
    ),
    call_bridge(exploration_simulate, _{id:Id, antecedent:Props, iteration:I1,
                                        attempt:Attempt}, Sim),
    maplist(entry, Explored1, Entries),
    call_bridge(exploration_best_plane, _{antecedents:Entries}, Best),
    (   Settings.curiosity == discover
    ->  append(Rest, SetAside, Away),
        discover_queue(Best, Explored1, Id, Props, Away, Rest, Settings, I1, Added, Queue),
        more(Added, Settings, Id, Props, Parent, Via, More),
        append(More, Queue, ANew)
    ;   paper_added(Best, Settings, Explored1, Rest, Added),
        append(Rest, Added, ANew)
    ),
    S1 = st(I1, Explored1, ANew, SetAside),
    format(string(State), "~k", [S1]),
    length(ANew, Left),
    findall(P, member(cand(P, _, _), Added), AddedProps),
    dict_pairs(Best.gradient, _, Gradient),
    findall(_{parameter:X, component:G},
            ( followed(Best, Settings),
              direction(Gradient, Best.mean, D), top(D, 5, Top), member(X-G, Top) ),
            Dir),
    format(string(ViaText), "~w", [Via]),
    Best0 = _{antecedent:Best.antecedent, expectation:Best.expectation,
              slope:Best.slope, mean:Best.mean, direction:Dir},
    (   Settings.curiosity == discover
    ->  findall(_{expectation:E, parameters:Xs},
                ( member(Dn, Best.directions), get_dict(expectation, Dn, E),
                  get_dict(moves, Dn, Ms),
                  findall(X, ( member(M, Ms), get_dict(parameter, M, X) ), Xs) ),
                Planes),
        BestT = Best0.put(_{significant:Best.significant, planes:Planes})
    ;   BestT = Best0
    ),
    Trace0 = _{iteration:I1, id:Id, antecedent:Props, parent:Parent, via:ViaText,
               simulations:Sim.simulations, failed:Sim.failed,
               best:BestT, added:AddedProps, a_new:Left},
    (   Settings.curiosity == discover
    ->  findall(T, ( member(probe(P, Sc, K, _, By), Probes),
                         probe_entry(P, Sc, K, By, T) ), ProbeTrace),
        Trace = Trace0.put(probes, ProbeTrace)
    ;   Trace = Trace0
    ),
    call_bridge(exploration_checkpoint, _{iteration:I1, state:State, trace:Trace,
                                          explored:I1, a_new:Left}, _).

%   choose(+State, +Settings, -Cand, -Attempt, -Rest, -Probes): the
%   candidate this iteration explores, the attempt whose pours its batch is
%   (0: the iteration's own), A_new without it and the candidates set
%   aside, and Probes, probe(Props, Score, Kept, Attempt, By) for each
%   candidate probed, By `novelty` (the next of A_new) or `fewest` (the
%   last attempt, where the pours are fewest: fewest/5).
%   Without probes (the paper's curiosity, probe(0), a_0 and more batches)
%   it is the head of A_new. Otherwise the first `probe` pours of the head's
%   batch are simulated, and it is explored when they show a new,
%   reproducible consequent (exploration_probe); else the next is probed,
%   at most `probe_attempts` of them, and the one whose probe scored best is
%   explored.
choose(st(I, Explored, [C|Rest], SetAside), Settings, Cand, Attempt, Rest1, Probes) :-
    (   unprobed(C, Settings)
    ->  Cand = C, Attempt = 0, Rest1 = Rest, Probes = []
    ;   I1 is I + 1,
        maplist(entry, Explored, Entries),
        append([C|Rest], SetAside, Away),
        exclusions(Explored, Away, Exclude),
        probe_loop([C|Rest], Entries-Exclude, Settings, I1, 0, novelty, [], Cand, Attempt,
                   Rest1, Probes)
    ).

unprobed(cand(_, _, Via), Settings) :-
    (   Settings.curiosity \== discover
    ;   Settings.probe =:= 0
    ;   Via = initial
    ;   Via = prior
    ;   Via = more(_, _)
    ), !.

probe_loop([C|Rest], Known, Settings, I1, K, By, Tried, Cand, Attempt, Rest1, Probes) :-
    Known = Entries-Exclude,
    C = cand(Props, _, _),
    call_bridge(exploration_probe, _{antecedents:Entries, antecedent:Props,
                                     iteration:I1, attempt:K, by:By}, R),
    Tried1 = [t(R.score, K, By, C)|Tried],
    K1 is K + 1,
    (   R.pass == true
    ->  probe_end(Tried1, K, Rest, Cand, Attempt, Rest1, Probes)
    ;   K1 < Settings.probe_attempts,
        Rest = [Next|_], \+ unprobed(Next, Settings)
    ->  (   K1 =:= Settings.probe_attempts - 1, K1 > 0, Settings.cover > 0,
            fewest(Rest, Exclude, Settings, I1, Rest2)
        ->  probe_loop(Rest2, Known, Settings, I1, K1, fewest, Tried1, Cand, Attempt, Rest1, Probes)
        ;   probe_loop(Rest, Known, Settings, I1, K1, novelty, Tried1, Cand, Attempt, Rest1, Probes)
        )
    ;   best_probe(Tried1, Best),
        probe_end(Tried1, Best, Rest, Cand, Attempt, Rest1, Probes)
    ).

%   fewest(+Rest, +Exclude, +Settings, +I, -Rest2): the last probe of a
%   step goes where the pours are fewest: to the candidate of A_new (Rest)
%   or of this step's random valid antecedents (jumps/4, none in Exclude)
%   whose rarest proposition the fewest pours so far hold, when fewer than
%   `cover` do (exploration_fewest; the earliest of equals). Rest2 is Rest
%   with it first. Fails when `cover` pours or more hold every proposition
%   of every candidate.
fewest(Rest, Exclude, Settings, I, [Chosen|Others]) :-
    include([C]>>( \+ unprobed(C, Settings) ), Rest, InQueue),
    jumps(Settings, I, Exclude, Far),
    findall(cand(P, none, jump), member(P, Far), Jumps),
    append(InQueue, Jumps, Pool),
    findall(P, member(cand(P, _, _), Pool), Cands),
    call_bridge(exploration_fewest, _{candidates:Cands, enough:Settings.cover}, Reply),
    Reply.index >= 0,
    nth0(Reply.index, Pool, Chosen),
    (   selectchk(Chosen, Rest, Others) -> true ; Others = Rest ).

%   probe_end(+Tried, +Chosen, +Rest, -Cand, -Attempt, -Rest, -Probes):
%   the attempt Chosen of Tried is explored, the others are set aside.
probe_end(Tried, Chosen, Rest, Cand, Chosen, Rest, Probes) :-
    memberchk(t(_, Chosen, _, Cand), Tried),
    reverse(Tried, InOrder),
    findall(probe(P, Sc, Kept, K, By),
            ( member(t(Sc, K, By, cand(P, _, _)), InOrder),
              ( K == Chosen -> Kept = true ; Kept = false ) ),
            Probes).

%   best_probe(+Tried, -K): the attempt whose probe scored best (the
%   earliest of equals).
best_probe(Tried, K) :-
    reverse(Tried, InOrder),
    findall(Key-A, ( member(t(Sc, A, _, _), InOrder), Key is -Sc ), Keyed),
    keysort(Keyed, [_-K|_]).

%   probe_entry(+Props, +Score, +Kept, +By, -Entry): a probe in the trace;
%   one that went where the pours are fewest (fewest/5) says so.
probe_entry(P, Sc, K, novelty, _{antecedent:P, score:Sc, kept:K}).
probe_entry(P, Sc, K, fewest, _{antecedent:P, score:Sc, kept:K, by:fewest}).

%   followed(+Best, +Settings): the best plane is followed (steep enough for
%   the paper's curiosity, significant for the discovering one).
followed(Best, Settings) :-
    (   Settings.curiosity == discover
    ->  Best.significant == true
    ;   Best.slope > Settings.threshold
    ).

%   The paper's step: modify/5 along the steepest plane's signed gradient.
paper_added(Best, Settings, Explored, Rest, Added) :-
    (   Best.slope > Settings.threshold
    ->  memberchk(ant(Best.antecedent, MProps, _, _), Explored),
        dict_pairs(Best.gradient, _, Gradient),
        direction(Gradient, Best.mean, Direction),
        exclusions(Explored, Rest, Exclude),
        modify(MProps, Direction, Settings.breadth, Exclude, Mods),
        findall(cand(P, Best.antecedent, via(Best.expectation, X, Sign)),
                member(mod(P, X, Sign), Mods), Added)
    ;   Added = []
    ).

%   more(+Added, +Settings, +Id, +Props, +Parent, +Via, -More): when no
%   plane led to a new antecedent (none is significant, or its moves are
%   all explored), the antecedent just explored is sampled again next (at
%   most `resample` more batches of it): planes that are undecided get more
%   pours before the exploration moves on or stops.
more(Added, Settings, Id, Props, Parent, Via, More) :-
    (   Via = more(_, K) -> true ; K = 0 ),
    (   Added == [], K < Settings.resample
    ->  K1 is K + 1,
        More = [cand(Props, Parent, more(Id, K1))]
    ;   More = []
    ).

%   discover_queue(+Best, +Explored, +Id, +Props, +Away, +Rest, +Settings, +I, -Added, -Queue):
%   the discovering step of iteration I, after the antecedent Id (Props).
%   Away are antecedents that are no candidates: A_new and those set aside
%   after their probe.
%   The candidates are those of modify_past/4 for every significant plane
%   and parameter of every antecedent with a significant plane (steepest
%   first), every valid antecedent one proposition away from Props
%   (neighbours/3), random valid antecedents (jumps/4), then A_new as it was
%   (Rest). Each gets its novelty (exploration_predict); Queue, the new
%   A_new, holds the most novel of those that reach the novelty level, at
%   most `queue` of them (ties in the order above). Added are the new ones
%   of Queue, in its order.
discover_queue(Best, Explored, Id, Props, Away, Rest, Settings, I, Added, Queue) :-
    exclusions(Explored, Away, Exclude0),
    foldl(follow(Explored), Best.followed, Exclude0-[], Exclude1-RevFollowed),
    append(RevFollowed, Followed),
    neighbours(Props, Exclude1, Near),
    findall(cand(P, Id, near), member(P, Near), Neighbours),
    append(Exclude1, Near, Exclude2),
    jumps(Settings, I, Exclude2, Far),
    findall(cand(P, none, jump), member(P, Far), Jumps),
    append([Followed, Neighbours, Jumps, Rest], Pool),
    (   Pool == []
    ->  Added = [], Queue = []
    ;   maplist(entry, Explored, Entries),
        findall(P, member(cand(P, _, _), Pool), Cands),
        call_bridge(exploration_predict, _{antecedents:Entries, candidates:Cands}, Reply),
        findall(Key-C, ( nth1(K, Pool, C), nth1(K, Reply.queued, true),
                         nth1(K, Reply.novelty, N), Key is -N ),
                Keyed),
        keysort(Keyed, Sorted),
        pairs_values(Sorted, Queue0),
        length(Queue0, Len),
        Keep is min(Len, Settings.queue),
        length(Queue, Keep),
        append(Queue, _, Queue0),
        append([Followed, Neighbours, Jumps], New),
        include([C]>>memberchk(C, New), Queue, Added)
    ).

%   jumps(+Settings, +Iteration, +Exclude, -New): Settings.jumps valid
%   antecedents drawn uniformly (validity:random_antecedents/3, seeded by
%   the run's seed and the iteration), none in Exclude.
jumps(Settings, I, Exclude, New) :-
    Seed is Settings.seed * 1000003 + I,
    random_antecedents(Seed, Settings.jumps, All),
    exclude([P]>>memberchk(P, Exclude), All, New0),
    list_to_set(New0, New).

follow(Explored, F, Exclude0-Acc0, Exclude-[Added|Acc0]) :-
    get_dict(antecedent, F, AId),
    get_dict(directions, F, Directions),
    memberchk(ant(AId, MProps, _, _), Explored),
    findall(move(E, X, Sign, Flip),
            ( member(Dn, Directions), get_dict(expectation, Dn, E),
              get_dict(moves, Dn, Ms), member(M, Ms),
              get_dict(parameter, M, X), get_dict(sign, M, Sign), get_dict(flip, M, Flip) ),
            Moves),
    modify_past(MProps, Moves, Exclude0, Mods),
    findall(cand(P, AId, via(E, X, Sign)), member(mod(P, E, X, Sign), Mods), Added),
    findall(P, member(mod(P, _, _, _), Mods), Cands),
    append(Exclude0, Cands, Exclude).

%!  neighbours(+Props:list, +Exclude:list, -New:list) is det.
%
%   The valid antecedents not in Exclude that differ from Props by one
%   proposition: one replaced by another value of its dimension, or one of
%   a dimension Props does not use added. Sorted, each once, in the order
%   of the vocabulary's parameters.
neighbours(Props0, Exclude, New) :-
    sort(Props0, Props),
    findall(P1, ( parameter(X, _, _, _, _), candidate_any(Props, X, P1),
                  \+ memberchk(P1, Exclude), valid_antecedent(P1) ),
            All),
    list_to_set(All, New).

exclusions(Explored, Away, Exclude) :-
    findall(P, ( member(ant(_, P, _, _), Explored)
               ; member(cand(P, _, _), Away)
               ; member(aside(_, _, P), Away) ), Exclude).

entry(ant(Id, Props, _, _), _{id:Id, antecedent:Props}).

% ----------------------------------------------------------------------
% Direction and modify

%!  direction(+Gradient:list, +MeanScore:number, -Direction:list) is det.
%
%   Gradient is a list Param-Component of a plane (score per normalised
%   unit). Direction is the same line, signed towards the other verdict:
%   where the antecedent's weighted mean score is above one half (the
%   expectation mostly holds), against the gradient, else along it.
direction(Gradient, Mean, Direction) :-
    (   Mean > 0.5 -> Sign = -1 ; Sign = 1 ),
    findall(X-D, ( member(X-G, Gradient), D is Sign * G ), Direction).

%!  modify(+Props:list, +Direction:list, +Breadth:integer, +Exclude:list, -New:list) is det.
%
%   New lists mod(Props1, Param, Sign) for antecedents Props1 (sorted)
%   obtained from Props by moving along Direction: for each of the Breadth
%   parameters with the largest components |D| of Direction (Sign is up for
%   D > 0, down for D < 0),
%
%     - if a proposition of Props draws the parameter, it is replaced by its
%       neighbour in its dimension (one rank up or down) that moves the
%       parameter's mean in the direction's sign;
%     - otherwise each proposition that draws the parameter, of a dimension
%       Props does not use, and that moves the parameter's mean in the
%       direction's sign from its prior mean, is added.
%
%   Only valid antecedents are kept, none that is in Exclude (a list of
%   sorted antecedents: those explored and those already in A_new), each
%   once, in the order of the parameters, then of the vocabulary.
modify(Props0, Direction, Breadth, Exclude, New) :-
    sort(Props0, Props),
    top(Direction, Breadth, Top),
    foldl(param_mods(Props), Top, [], RevMods),
    reverse(RevMods, Mods0),
    exclude(excluded(Exclude), Mods0, New).

excluded(Exclude, mod(P, _, _)) :- memberchk(P, Exclude).

param_mods(Props, X-D, Acc0, Acc) :-
    (   D > 0 -> Sign = up ; Sign = down ),
    findall(P1, candidate(Props, X, D, P1), Cands),
    foldl(add_new(X, Sign), Cands, Acc0, Acc).

add_new(X, Sign, P, Acc0, Acc) :-
    (   memberchk(mod(P, _, _), Acc0) -> Acc = Acc0 ; Acc = [mod(P, X, Sign)|Acc0] ).

%   top(+Direction, +K, -Top): the K pairs with the largest |component|
%   above zero, largest first (ties in parameter order). top/4 keeps only
%   those of at least Share times the largest.
top(Direction, K, Top) :-
    top(Direction, K, 0, Top).

top(Direction, K, Share, Top) :-
    findall(N-(X-D), ( nth1(I, Direction, X-D), D =\= 0, N0 is -abs(D), N = N0-I ), Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, All0),
    (   All0 = [_-D0|_]
    ->  Min is abs(D0) * Share,
        include(large(Min), All0, All)
    ;   All = []
    ),
    length(All, Len),
    Take is min(K, Len),
    length(Top, Take),
    append(Top, _, All).

large(Min, _-D) :- abs(D) >= Min.

candidate(Props, X, D, Props1) :-
    (   member(P, Props), model(P, X, _)
    ->  proposition(P, Dim, R, _),
        ( R1 is R + 1 ; R1 is R - 1 ),
        proposition(P1, Dim, R1, _),
        selectchk(P, Props, Rest),
        sort([P1|Rest], Props1)
    ;   with_new_dimension(Props, X, Props1)
    ),
    parameter_mean(Props, X, M0),
    parameter_mean(Props1, X, M1),
    (M1 - M0) * D > 0,
    valid_antecedent(Props1).

%!  modify_past(+Props:list, +Moves:list, +Exclude:list, -New:list) is det.
%
%   New lists mod(Props1, Expectation, Param, Sign) for the antecedents
%   Props1 (sorted) that move the pours of Props past the point where a
%   plane's verdict flips. Moves lists move(Expectation, Param, Sign, Flip):
%   the plane of Expectation says its verdict flips where Param passes the
%   value Flip (theory units) going up or down (Sign). For each move,
%
%     - if a proposition of Props draws Param, it is replaced by any other
%       proposition of its dimension (any rank, not only the next);
%     - otherwise any proposition that draws Param, of a dimension Props
%       does not use, is added;
%
%   keeping the valid antecedents not in Exclude whose mean of Param lies
%   past Flip (parameter_mean/3); when none does, those that move the mean
%   farthest towards it. Each antecedent once (its first move), in the
%   order of Moves, then of the vocabulary.
modify_past(Props0, Moves, Exclude, New) :-
    sort(Props0, Props),
    foldl(move_mods(Props, Exclude), Moves, [], RevMods),
    reverse(RevMods, New).

move_mods(Props, Exclude, move(E, X, Sign, Flip), Acc0, Acc) :-
    parameter_mean(Props, X, M0),
    findall(Gain-P1,
            ( candidate_any(Props, X, P1),
              \+ memberchk(P1, Exclude),
              parameter_mean(P1, X, M1),
              signed(Sign, M1 - M0, Gain),
              Gain > 0,
              valid_antecedent(P1) ),
            Moved),
    signed(Sign, Flip - M0, Need),
    findall(P1, ( member(G-P1, Moved), G >= Need ), Past),
    (   Past \== []
    ->  Chosen = Past
    ;   Moved == []
    ->  Chosen = []
    ;   aggregate_all(max(G), member(G-_, Moved), Far),
        findall(P1, member(Far-P1, Moved), Chosen)
    ),
    foldl(add_move(E, X, Sign), Chosen, Acc0, Acc).

add_move(E, X, Sign, P, Acc0, Acc) :-
    (   memberchk(mod(P, _, _, _), Acc0) -> Acc = Acc0 ; Acc = [mod(P, E, X, Sign)|Acc0] ).

signed(up, D, V) :- V is D.
signed(down, D, V) :- V is -(D).

%   candidate_any(+Props, +X, -Props1): Props with the proposition that
%   draws X replaced by another of its dimension, or, when none draws X,
%   with a proposition that draws X added from a dimension Props does not use.
candidate_any(Props, X, Props1) :-
    (   member(P, Props), model(P, X, _)
    ->  proposition(P, Dim, _, _),
        proposition(P1, Dim, _, _),
        P1 \== P,
        selectchk(P, Props, Rest),
        sort([P1|Rest], Props1)
    ;   with_new_dimension(Props, X, Props1)
    ).

%   with_new_dimension(+Props, +X, -Props1): Props with a proposition that
%   draws X added, from a dimension Props does not use.
with_new_dimension(Props, X, Props1) :-
    findall(Dim, ( member(P, Props), proposition(P, Dim, _, _) ), Dims),
    proposition(P1, Dim1, _, _),
    model(P1, X, _),
    \+ memberchk(Dim1, Dims),
    sort([P1|Props], Props1).

%!  parameter_mean(+Props:list, +Param, -Mean:number) is det.
%
%   The mean of Param under the antecedent's generative models (its
%   prior's mean if no proposition of Props draws it), clipped to its
%   bounds; a relative model adds its offset's mean to its base's mean.
parameter_mean(Props, X, Mean) :-
    parameter(X, _, _, Lo, Hi),
    (   member(P, Props), model(P, X, Model)
    ->  model_mean(Model, Props, Lo, Hi, Mean)
    ;   prior(X, uniform(PL, PH)),
        Mean is (PL + PH) / 2
    ).

model_mean(uniform(L, H), _, Lo, Hi, Mean) :-
    Mean is (max(L, Lo) + min(H, Hi)) / 2.
model_mean(relative(Base, L, H), Props, Lo, Hi, Mean) :-
    parameter_mean(Props, Base, MB),
    Mean is max(Lo, min(Hi, MB + (L + H) / 2)).

% ----------------------------------------------------------------------
% Qualify and the learned theory

learned(Explored, SetAside, Settings, Stop, Left, Facts) :-
    maplist(entry, Explored, Entries),
    call_bridge(exploration_qualify, _{antecedents:Entries, mode:Settings.qualify}, Reply),
    setting_facts(Settings, Reply, Stop, Explored, Left, SettingFacts),
    findall(set_aside(I, K, P), ( member(aside(I, K, Ps), SetAside), member(P, Ps) ), AsideFacts),
    rule_facts(Explored, Reply.antecedents, RuleFacts),
    append([SettingFacts, AsideFacts, RuleFacts], Facts).

setting_facts(Settings, Reply, Stop, Explored, Left, Facts) :-
    length(Explored, N),
    Permille is round(Settings.threshold * 1000),
    RidgePermille is round(Settings.ridge * 1000),
    NoveltyPermille is round(Settings.novelty * 1000),
    string_value(Reply.oracle_version, Version),
    (   Settings.curiosity == discover
    ->  Threshold = [ setting(curiosity, discover),
                      setting(significance_permille, Permille),
                      setting(permutations, Settings.permutations),
                      setting(resample, Settings.resample),
                      setting(novelty_permille, NoveltyPermille),
                      setting(queue, Settings.queue),
                      setting(jumps, Settings.jumps),
                      setting(probe, Settings.probe),
                      setting(probe_attempts, Settings.probe_attempts),
                      setting(cover, Settings.cover),
                      setting(prior, Settings.prior) ]
    ;   Threshold = [ setting(threshold_permille, Permille) ]
    ),
    append([ [ setting(oracle, Settings.oracle),
               setting(oracle_version, Version),
               setting(seed, Settings.seed),
               setting(samples, Settings.samples),
               setting(max_rules, Settings.max_rules) ],
             Threshold,
             [ setting(breadth, Settings.breadth),
               setting(ridge_permille, RidgePermille),
               setting(qualify, Settings.qualify),
               setting(explored, N),
               setting(simulations, Reply.simulations),
               setting(failed_simulations, Reply.failed),
               setting(stopped, Stop),
               setting(a_new_left, Left) ] ], Facts1),
    findall(setting(initial, P), member(P, Settings.initial), Initial),
    append(Facts1, Initial, Facts).

string_value(V, S) :- ( string(V) -> S = V ; atom_string(V, S) ).

%!  rule_facts(+Explored:list, +Qualified:list, -Facts:list) is det.
%
%   The facts of the learned rules: for each explored antecedent
%   ant(Id, Props, Parent, Via) and its qualified outcome (a dict with
%   `outcomes`, a list of dicts with expectation, holds, confidence_permille
%   and score_permille, and the antecedent's `simulations` and
%   `weight_mass_permille`, and for the discovering curiosity `batches`,
%   its batches of pours), one defeasible rule per outcome literal, its
%   body facts, learned/1 and its provenance.
rule_facts(Explored, Qualified, Facts) :-
    foldl(antecedent_facts(Qualified), Explored, Fs, []),
    Facts = Fs.

antecedent_facts(Qualified, ant(Id, Props, Parent, Via), Facts, Tail) :-
    member(Q, Qualified), Q.id == Id, !,
    foldl(outcome_facts(Id, Props, Parent, Via, Q), Q.outcomes, Facts, Tail).

outcome_facts(AId, Props, Parent, Via, Q, O, Facts, Tail) :-
    sub_atom(AId, 1, _, 0, Num),
    atomic_list_concat([r, Num, '_', O.expectation], Id),
    (   O.holds == true -> Head = O.expectation ; Head = neg(O.expectation) ),
    findall(body(Id, P), member(P, Props), Bodies),
    via_facts(Id, Via, ViaFacts0),
    (   get_dict(batches, Q, B)
    ->  ViaFacts = [provenance(Id, batches, B)|ViaFacts0]
    ;   ViaFacts = ViaFacts0
    ),
    Prov = [ provenance(Id, antecedent, AId),
             provenance(Id, parent, Parent),
             provenance(Id, simulations, Q.simulations),
             provenance(Id, weight_mass_permille, Q.weight_mass_permille),
             provenance(Id, confidence_permille, O.confidence_permille),
             provenance(Id, score_permille, O.score_permille)
           | ViaFacts ],
    append([[rule(Id, defeasible, Head)], Bodies, [learned(Id)], Prov], Fs),
    append(Fs, Tail, Facts).

via_facts(_, initial, []).
via_facts(_, prior, []).
via_facts(_, near, []).
via_facts(_, jump, []).
via_facts(Id, via(E, X, Sign), [ provenance(Id, followed, E),
                                 provenance(Id, direction, X),
                                 provenance(Id, sign, Sign) ]).

%!  write_theory(+File, +Settings:dict, +Facts:list) is det.
%
%   Write Facts to File, in the common subset of Prolog and ASP, with a
%   header saying what the file is. The file is written beside under a
%   temporary name and renamed, so File is never half-written.
write_theory(File, Settings, Facts) :-
    file_directory_name(File, Dir),
    make_directory_path(Dir),
    current_prolog_flag(pid, Pid),
    format(atom(Tmp), "~w.~w.tmp", [File, Pid]),
    setup_call_cleanup(
        open(Tmp, write, Out, [encoding(utf8)]),
        write_facts(Out, Settings, Facts),
        close(Out)),
    rename_file(Tmp, File).

write_facts(Out, Settings, Facts) :-
    format(Out, "% A theory of pouring learned by curiosity-driven exploration~n", []),
    format(Out, "% (pantarhei explore, oracle ~w, seed ~w).~n", [Settings.oracle, Settings.seed]),
    format(Out, "%~n", []),
    format(Out, "% Ground facts, read by SWI-Prolog and clingo alike:~n", []),
    format(Out, "%   rule(Id, defeasible, Head): Head is an expectation, or neg(E) when it fails;~n", []),
    format(Out, "%   body(Id, Prop): a scene proposition of the rule's antecedent;~n", []),
    format(Out, "%   learned(Id): a learned rule (superiority from specificity);~n", []),
    format(Out, "%   provenance(Id, Key, Value): where the rule comes from (antecedent,~n", []),
    format(Out, "%   parent antecedent, simulations with a weight, their weight mass and the~n", []),
    format(Out, "%   verdict's confidence in permille, and the plane, parameter and sign~n", []),
    format(Out, "%   that produced the antecedent);~n", []),
    (   get_dict(curiosity, Settings, discover)
    ->  format(Out, "%   setting(Key, Value): how the exploration ran;~n", []),
        format(Out, "%   set_aside(Iteration, Attempt, Prop): a proposition of a candidate whose~n", []),
        format(Out, "%   probe (the Attempt-th of the Iteration, from 0) set it aside.~n~n", [])
    ;   format(Out, "%   setting(Key, Value): how the exploration ran.~n~n", [])
    ),
    forall(member(F, Facts),
           (   ( F = rule(_, _, _) -> nl(Out) ; true ),
               write_term(Out, F, [quoted(true), spacing(next_argument)]),
               write(Out, '.\n')
           )).

% ----------------------------------------------------------------------
% The oracle at the prompt

%!  sample(+Props:list, +N:integer, +Seed:integer, -Rows:list) is det.
%
%   Rows are N parameterizations drawn from P(p|Props): lists of 30 numbers
%   in the vocabulary's parameter order (theory units).
sample(Props, N, Seed, Rows) :-
    call_bridge(oracle_sample, _{antecedent:Props, n:N, seed:Seed}, Reply),
    Rows = Reply.rows.

%!  describe(+Row:list, -Props:list) is det.
%
%   Props are the propositions whose generative models hold the
%   parameterization Row (30 numbers in the vocabulary's parameter order):
%   per dimension the value whose support contains Row, none where it falls
%   between values. Every row that sample/4 draws for an antecedent is
%   described by a superset of it.
describe(Row, Props) :-
    call_bridge(oracle_describe, _{rows:[Row]}, Reply),
    Reply.props = [Props0],
    maplist([P0, P]>>atom_string(P, P0), Props0, Props).

%!  simulate(+Rows:list, +Options:list, -Scores:list) is det.
%
%   Scores are the 9 expectation scores of each row (a list of
%   Expectation-Score pairs per row; a failed simulation scores nan).
%   Options: oracle(Name) (default: theory/defaults.pl), store(File), executor(E),
%   workers(N). Results are kept in the store, and stored ones are not
%   simulated again.
simulate(Rows, Options, Scores) :-
    default(oracle, DefaultOracle),
    option(oracle(Oracle), Options, DefaultOracle),
    option(executor(Executor), Options, local),
    Request0 = _{rows:Rows, oracle:Oracle, executor:Executor},
    (   option(store(Store), Options)
    ->  absolute_file_name(Store, Abs), put_dict(store, Request0, Abs, Request1)
    ;   Request1 = Request0
    ),
    (   option(workers(W), Options) -> put_dict(workers, Request1, W, Request) ; Request = Request1 ),
    call_bridge(oracle_simulate, Request, Reply),
    findall(E, expectation(E, _, _), Es),
    findall(Row, ( member(S, Reply.scores), pairs_keys_values(Row, Es, S) ), Scores).

% ----------------------------------------------------------------------
% The bridge

:- multifile prolog:message//1.

prolog:message(exploration_error(Text)) -->
    [ '~w'-[Text] ].

%   call_bridge(+Name, +Request:dict, -Reply:dict): call the foreign
%   predicate bridge:Name with the request as JSON text.
call_bridge(Name, Request, Reply) :-
    (   current_predicate(bridge:Name/2)
    ->  true
    ;   throw(exploration_error("the oracle is not loaded: start Prolog with `pantarhei prolog`"))
    ),
    atom_json_dict(Text, Request, [width(0)]),
    Goal =.. [Name, Text, ReplyText],
    (   call(bridge:Goal)
    ->  true
    ;   format(string(M), "~w failed", [Name]),
        throw(exploration_error(M))
    ),
    atom_json_dict(ReplyText, Reply0, [value_string_as(atom)]),
    (   get_dict(error, Reply0, Message)
    ->  string_value(Message, M),
        throw(exploration_error(M))
    ;   Reply = Reply0
    ).
