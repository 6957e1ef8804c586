% The messages of the checks of a theory file that both readers make,
% written once and read by SWI-Prolog (theory/defeasible.pl:
% check_message/3) and by Python (pantarhei.theory.check_message), so that
% a bad file gets the same words from either, after its `file:line: `.
% check_message(Key, Format): Format is format/2's, with ~w alone (each
% ~w is the next argument, written as it is), which both render alike.
% tests/theory/test_check_messages.py gives both readers the same bad
% files and compares what they say.

% A rule could beat itself (and a literal and its complement both be
% concluded): the cycle's rules, joined by " > ", first and last the same.
check_message(superiority_cycle,
  "the superiority relation has a cycle, ~w: it must be acyclic").
