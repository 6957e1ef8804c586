:- module(plunit_helpers,
          [ text_file/2,            % +Text, -File
            load_theory_text/1      % +Text
          ]).
/** <module> Helpers shared by the plunit tests of theory/

Tests write small theories as text; these put such text in a temporary file
and load it, so each .plt does not keep its own copy.
*/

:- use_module(defeasible).

%!  text_file(+Text, -File) is det.
%
%   File is a new temporary file holding Text (deleted when the process
%   ends, or by the caller).
text_file(Text, File) :-
    tmp_file_stream(text, File, S),
    call_cleanup(write(S, Text), close(S)).

%!  load_theory_text(+Text) is det.
%
%   Make the theory written in Text (native format) the current theory of
%   defeasible.pl.
load_theory_text(Text) :-
    text_file(Text, File),
    call_cleanup(load_theory(File), delete_file(File)).
